// SPDX-License-Identifier: MIT
// Hourglass (zero-energy mode) control, DESIGN §4. TLSPH's F averages over the neighbourhood,
// so a pattern that alternates from particle to particle costs no strain energy. This penalty
// acts on the part of each bond that the particle's affine field F does not explain:
//   e_ab = ½ (F_a + F_b) X_ab − x_ab   (X_ab = X_b − X_a, x_ab = x_b − x_a),
//   s_ab = e_ab · x̂_ab  (bond too short: s > 0),
//   f_a −= k_ab s_ab x̂_ab,  f_b += k_ab s_ab x̂_ab,
//   k_ab = α E ½ (V_a + V_b) ω W_ab / |X_ab|²   (ω_a = ω_b = ω within a space).
// It is central and antisymmetric (conserves linear and angular momentum) and vanishes for any
// affine motion. Σ_b ω_b W_ab ≈ 1, so α is the penalty stiffness relative to E·Δx per particle.
//
// In plastic flow the material resists a deformation with far less than E, while e_ab, O(|X|³)
// in smooth flow (and O(|X|²) at a boundary, where F is one-sided), is not zero: a penalty with
// E stiffens the flow itself, by an error first order in the spacing that dominated the Taylor
// bar's footprint on coarse layouts (docs/theory.md "Hourglass control in plastic flow"). With
// HourglassModulus::Secant each particle's penalty takes the secant modulus of its deviatoric
// response,
//   s_a = G_s/G = σ_eq/(σ_eq + 3G ε̄p)   (1 while it has not yielded, ε̄p = 0),
// and a pair k_ab ½(s_a + s_b): elastic materials and unyielded particles keep α E exactly. It is
// not the default: it changes how a damaged band fails, and the fracture cases are not yet
// re-measured with it (docs/theory.md).
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace gsph {

/// Coefficient κ_ab of the hourglass force on a from b, f = −κ_ab x_ab, i.e. k_ab s_ab/|x_ab|
/// written without a square root: κ_ab = α E w_ab (ē·x_ab)/(|X_ab|² |x_ab|²) with
/// ē·x_ab = predicted − x2, predicted = ½(F_a + F_b) X_ab · x_ab, x2 = |x_ab|², X2 = |X_ab|²,
/// pairWeight w_ab = ½ (V_a + V_b) ω W_ab. T is double (one pair) or a strip (core/lanes.hpp).
template <class T>
[[gnu::always_inline]] inline T hourglassPairCoefficient(double alphaE, const T& predicted,
                                                         const T& x2, const T& X2,
                                                         const T& pairWeight) {
    return alphaE * pairWeight * (predicted - x2) / (X2 * x2);
}

/// The modulus of a particle's hourglass penalty: E throughout (s_a = 1) or the secant one of
/// its deviatoric response (s_a above).
enum class HourglassModulus { Elastic, Secant };

/// s_a of a particle with von Mises stress σ_eq [Pa], shear modulus G [Pa] and effective plastic
/// strain ε̄p: 1 for ε̄p = 0.
inline double hourglassPlasticScale(double vonMises, double shearModulus, double plasticStrain) {
    if (!(plasticStrain > 0.0)) return 1.0;
    return vonMises / (vonMises + 3.0 * shearModulus * plasticStrain);
}

/// The hourglass force on a from b (general pair-list path).
inline Vec3 hourglassPairForce(double alphaE, const Mat3& Fa, const Mat3& Fb, const Vec3& XabRef,
                               const Vec3& xab, double pairWeight) {
    const double predicted = 0.5 * ((Fa + Fb) * XabRef).dot(xab);  // ½(F_a + F_b) X_ab · x_ab
    return -hourglassPairCoefficient<double>(alphaE, predicted, xab.squaredNorm(),
                                             XabRef.squaredNorm(), pairWeight) *
           xab;
}

}  // namespace gsph
