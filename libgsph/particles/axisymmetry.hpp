// SPDX-License-Identifier: MIT
// The axisymmetric form of a 2-D run (Dimension::axisymmetric; docs/theory.md "Axisymmetric
// runs"): the x-y plane is the (r, z) half-plane of a body of revolution, x = r the radius, and
// each particle stands for the ring its cell sweeps about the y axis. What changes against plane
// strain is one factor and one entry:
//   * the ring's volume V = 2π R A (A the cell's area, R = X_x its reference radius): the energy
//     Σ V Ψ(F), the mass ρ0 V and every pair term weighted by V see rings;
//   * the hoop entry of F (the out-of-plane zz one): F_zz = r/R, Ḟ_zz = v_r/R, so L_zz = v_r/r;
//     the hoop stress then does work through −∂E/∂x_a = −V_a P_zz/R_a e_r
//     (forces/hoop_stress_stage.hpp).
// No particle sits on the axis (cell centres have R ≥ half a cell), so r/R and 1/R are finite;
// the weak form's boundary term on the axis carries the factor 2πr = 0, so the axis needs no
// condition of its own.
#pragma once

#include <numbers>

#include "core/types.hpp"

namespace gsph {

/// Volume of a ring per unit area of its cross-section: 2π R.
inline double ringFactor(const Vec3& X) {
    return 2.0 * std::numbers::pi * X[0];
}

/// F_zz of a particle at reference X and current x: the hoop stretch r/R.
inline double hoopStretch(const Vec3& X, const Vec3& x) {
    return x[0] / X[0];
}

/// Ḟ_zz of a particle at reference X moving at v: v_r/R.
inline double hoopStretchRate(const Vec3& X, const Vec3& v) {
    return v[0] / X[0];
}

}  // namespace gsph
