// SPDX-License-Identifier: MIT
// The material-point driver: one particle's deformation gradient driven along a prescribed
// path, through the same update as the solver's step (L = Ḟ F_{n+½}^{-1}, D = sym L,
// W = skew L, then the body's model), so a user can calibrate a material and the tests can
// compare it with closed forms.
//
// Paths (LoadingPath):
//   deformation gradient  F(t) piecewise linear through given (t_i, F_i), `substeps` increments
//                         per segment; strain column = equivalent logarithmic (Hencky) strain
//   uniaxial strain       F = diag(λ, 1, 1), λ = exp(ε̇ t); strain = ln λ
//   uniaxial stress       F = diag(λ, μ, μ), λ = exp(ε̇ t), μ found each increment (secant) so
//                         that σ_yy = σ_zz = 0 to 1e-10 E + 1e-9 |σ_xx|; strain = ln λ
//   simple shear          F = I + γ e_x ⊗ e_y, γ = γ̇ t; strain = γ
// at a constant rate (negative: compression) from 0 to `finalStrain` in `steps` increments.
// Throws InputError for a bad path, NumericalError if the lateral iteration fails.
#pragma once

#include <optional>
#include <vector>

#include "materials/material.hpp"

namespace gsph {

struct LoadingPath {
    enum class Kind { DeformationGradient, UniaxialStrain, UniaxialStress, SimpleShear };
    Kind kind = Kind::UniaxialStress;
    // Kind::DeformationGradient: F at increasing times, F[0] = I at times[0] (≥ 2 points).
    std::vector<double> times;
    std::vector<Mat3> F;
    int substeps = 100;  ///< increments per segment of the F table
    // Compact forms.
    double strainRate = 0.0;   ///< ε̇ = d ln λ/dt (γ̇ for simple shear) [1/s]
    double finalStrain = 0.0;  ///< ln λ (γ for simple shear) at the end; same sign as strainRate
    int steps = 1000;          ///< increments of the whole path
    // Both.
    int outputEvery = 1;  ///< keep every Nth increment (the last one always)
    std::optional<double>
        temperature;  ///< initial T [K] (default: the material's room temperature)
};

/// One row of the driver's output.
struct MaterialPointRecord {
    double time = 0.0;
    double strain = 0.0;  ///< the path's strain measure (see above)
    Mat3 F = Mat3::Identity();
    Mat3 cauchy = Mat3::Zero();
    double plasticStrain = 0.0;
    double temperature = 0.0;
    double damage = 0.0;
    double plasticWork = 0.0;  ///< accumulated Σ Δw_p/ρ [J/kg]
};

/// Runs the path; the first record is the initial state (t = 0, σ = 0).
std::vector<MaterialPointRecord> driveMaterialPoint(const Material& material,
                                                    const LoadingPath& path);

/// Equivalent logarithmic strain √(⅔ dev ln V : dev ln V), V² = F F^T.
double equivalentLogStrain(const Mat3& F);

}  // namespace gsph
