// SPDX-License-Identifier: MIT
// Hourglass (zero-energy mode) control, DESIGN §4. TLSPH's F averages over the neighbourhood,
// so a pattern that alternates from particle to particle costs no strain energy. This penalty
// acts on the part of each bond that the particle's affine field F does not explain:
//   e_ab = ½ (F_a + F_b) X_ab − x_ab   (X_ab = X_b − X_a, x_ab = x_b − x_a),
//   s_ab = e_ab · x̂_ab  (bond too short: s > 0),
//   f_a −= k_ab s_ab x̂_ab,  f_b += k_ab s_ab x̂_ab,
//   k_ab = α E ½ (V_a ω_b + V_b ω_a) W_ab / |X_ab|².
// It is central and antisymmetric (conserves linear and angular momentum) and vanishes for any
// affine motion. Σ_b ω_b W_ab ≈ 1, so α is the penalty stiffness relative to E·Δx per particle.
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace gsph {

/// k_ab · s_ab: the signed magnitude of the hourglass pair force along x̂_ab, and x̂_ab.
inline double hourglassPairForce(double alphaE, const Mat3& Fa, const Mat3& Fb, const Vec3& XabRef,
                                 const Vec3& xab, double pairWeight, Vec3& direction) {
    const double d = xab.norm();
    direction = xab / d;
    const double s = (0.5 * ((Fa + Fb) * XabRef) - xab).dot(direction);
    return alphaE * pairWeight / XabRef.squaredNorm() * s;
}

}  // namespace gsph
