// SPDX-License-Identifier: MIT
// Analytic generalized spaces: smooth maps X(s) from the unit cube s ∈ [0,1]^3 to physical
// space, laid on a uniform θ-lattice (DESIGN §2) so the core can be verified before any mesh
// exists. A lattice of n_d cells per index puts a particle at θ = (i+½)Δθ, s = θ/(n Δθ), with
// X = X(s) and volume = Gauss quadrature (3 points per index) of det ∂X/∂θ over its cell.
//
// Maps provided: a graded box (separable; one-sided or symmetric grading per axis, spacing
// ratio as input), a cylindrical annulus (r(s1), φ(s2), z(s3); periodic in φ when it closes),
// and a wavy box (a non-separable smooth perturbation of a box).
#pragma once

#include <array>
#include <functional>

#include "particles/reference.hpp"

namespace gsph {

/// Smooth 1-D grading x(s) on [0,1] → [0,1]; `ratio` = largest / smallest spacing.
struct AxisGrading {
    enum class Kind { Uniform, OneSided, Symmetric };
    Kind kind = Kind::Uniform;
    double ratio = 1.0;  ///< OneSided: spacing grows from s=0 to s=1; Symmetric: fine at both ends

    double x(double s) const;
    double dx(double s) const;
};

struct AnalyticMap {
    std::function<Vec3(const Vec3&)> position;  ///< X(s)
    std::function<Mat3(const Vec3&)> jacobian;  ///< ∂X/∂s
    std::array<bool, 3> periodic = {false, false, false};
};

/// Box [origin, origin + lengths], graded per axis.
AnalyticMap gradedBoxMap(const Vec3& lengths, const std::array<AxisGrading, 3>& grading,
                         const Vec3& origin = Vec3::Zero());

/// Annulus sector ri ≤ r ≤ ro, phi0 ≤ φ ≤ phi1, 0 ≤ z ≤ height; periodic in φ if it spans 2π.
AnalyticMap annulusMap(double ri, double ro, double phi0, double phi1, double height,
                       const AxisGrading& radial = {});

/// X = L ∘ (s + ε (sin πs2 sin πs3, sin πs3 sin πs1, sin πs1 sin πs2)): non-separable, smooth.
AnalyticMap wavyBoxMap(const Vec3& lengths, double epsilon);

/// Lattice of `cells` per index (cells[2] = 1 for dimension 2) over `map`, one body of
/// density `density`. Returns a Reference with X, θ, volume, mass, body, space and one
/// LatticeSpace filled (Δθ = 1); pairs and geometry still to be built.
Reference latticeReference(const AnalyticMap& map, int dimension, const std::array<int, 3>& cells,
                           double density, double kappa, Index body = 0);

/// Particle indices of a lattice built by latticeReference: a = i + n0 (j + n1 k).
inline Index latticeIndex(const std::array<int, 3>& cells, int i, int j, int k) {
    return static_cast<Index>(i + cells[0] * (j + cells[1] * k));
}

}  // namespace gsph
