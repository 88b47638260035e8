// SPDX-License-Identifier: MIT
// Monaghan-type artificial viscosity of the paper (Eq. for Π_ab), as a pair pressure.
//   π_ab = (−β1 c̄ φ + β2 φ²)/ρ̄  if v_ab·x_ab < 0, else 0,
//   φ = h_ab (v_ab·x_ab)/(|x_ab|² + 0.01 h_ab²),  c̄, ρ̄ = pair means of sound speed and
//   current density, v_ab = v_a − v_b, x_ab = x_a − x_b.
// h_ab = ½(h_a + h_b), with each particle's physical smoothing length from its metric,
// h_a = κΔθ (det ∂X/∂θ)^{1/d} (DESIGN §4; spaces/metric.hpp). The paper's Π_ab = J F^{-T} π_ab (its
// transpose convention fixed) enters the total Lagrangian force like a pressure q_ab = ρ̄² π_ab:
// forces/internal_force.hpp.
//
// The compression switch (docs/theory.md "Artificial viscosity: the compression switch") scales
// a pair's coefficients by ᾱ_ab = ½(α_a + α_b), each particle's
//   α_a = M_a² / (M_a² + M0²),   M_a = h_a max(−tr D_a, 0) / c_a,
// M_a the compression Mach number of its volumetric strain rate (the velocity jump across one
// smoothing length that compresses the material, over the sound speed). A shock front has
// M ≈ u_p/(2c) whatever the resolution, so it keeps the viscosity; isochoric plastic flow and
// shear (tr D = 0) and elastic waves of small amplitude (M ≪ M0) do not, which is where the
// constant coefficients turned plastic flow into viscous flow and damped elastic rebounds.
// M0 = 0 keeps the constant coefficients (α = 1).
#pragma once

#include "core/lanes.hpp"
#include "core/strip_mat3.hpp"
#include "core/types.hpp"

namespace gsph {

struct ViscosityCoefficients {
    double linear = 0.0;     ///< β1
    double quadratic = 0.0;  ///< β2
    /// M0 of the compression switch: the compression Mach number at which the viscosity is
    /// half on (0 = off: the coefficients act in full on every approaching pair).
    double switchMach = 0.0;
    bool enabled() const { return linear != 0.0 || quadratic != 0.0; }
};

/// What a case gets unless it sets [run] viscosity and viscosity_switch.
inline constexpr ViscosityCoefficients kDefaultViscosity{1.0, 1.0, 0.01};

/// The switch α_a ∈ [0, 1] of a particle with smoothing length h [m], volumetric strain rate
/// trD = tr D [1/s] and sound speed c [m/s]; 1 when the switch is off. T: double or a strip
/// type (one particle per lane, core/strip_mat3.hpp).
template <class T>
[[gnu::always_inline]] inline T viscositySwitch(const ViscosityCoefficients& coefficients,
                                                const T& h, const T& trD, const T& c) {
    if (coefficients.switchMach == 0.0) return T{} + 1.0;
    const T mach = h * maxOf(-trD, T{} + 0.0) / c;
    const double m0 = coefficients.switchMach;
    return mach * mach / (mach * mach + m0 * m0);
}

/// Pair pressure q_ab = ρ̄² π_ab = ᾱ ρ̄ (−β1 c̄ φ + β2 φ²) [Pa], 0 for separating pairs, with
/// ᾱ = ½(α_a + α_b) the pair's switch (1 without it).
/// Takes the scalars vx = v_ab·x_ab and x2 = |x_ab|², and selects instead of branching; T is
/// double (one pair) or a strip type (Lanes2, Lanes4: a strip of pairs, core/lanes.hpp).
template <class T>
[[gnu::always_inline]] inline T viscousPairPressure(const ViscosityCoefficients& c, const T& vx,
                                                    const T& x2, const T& hab, const T& cbar,
                                                    const T& rhobar, const T& alphabar) {
    const T phi = hab * vx / (x2 + 0.01 * hab * hab);
    const T q = alphabar * (rhobar * (-c.linear * cbar * phi + c.quadratic * phi * phi));
    return whereNegative(vx, q);
}

}  // namespace gsph
