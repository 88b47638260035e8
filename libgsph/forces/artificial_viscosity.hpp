// SPDX-License-Identifier: MIT
// Monaghan-type artificial viscosity of the paper (Eq. for Π_ab), as a pair pressure.
//   π_ab = (−β1 c̄ φ + β2 φ²)/ρ̄  if v_ab·x_ab < 0, else 0,
//   φ = h_ab (v_ab·x_ab)/(|x_ab|² + 0.01 h_ab²),  c̄, ρ̄ = pair means of sound speed and
//   current density, v_ab = v_a − v_b, x_ab = x_a − x_b.
// h_ab = ½(h_a + h_b), with each particle's physical smoothing length from its metric,
// h_a = κΔθ (det ∂X/∂θ)^{1/d} (DESIGN §4; spaces/metric.hpp). The paper's Π_ab = J F^{-T} π_ab (its
// transpose convention fixed) enters the total Lagrangian force like a pressure q_ab = ρ̄² π_ab:
// forces/internal_force.hpp.
#pragma once

#include "core/lanes.hpp"
#include "core/types.hpp"

namespace gsph {

struct ViscosityCoefficients {
    double linear = 0.0;     ///< β1
    double quadratic = 0.0;  ///< β2
    bool enabled() const { return linear != 0.0 || quadratic != 0.0; }
};

/// Pair pressure q_ab = ρ̄² π_ab = ρ̄ (−β1 c̄ φ + β2 φ²) [Pa], 0 for separating pairs.
/// Takes the scalars vx = v_ab·x_ab and x2 = |x_ab|², and selects instead of branching; T is
/// double (one pair) or a strip type (Lanes2, Lanes4: a strip of pairs, core/lanes.hpp).
template <class T>
[[gnu::always_inline]] inline T viscousPairPressure(const ViscosityCoefficients& c, const T& vx,
                                                    const T& x2, const T& hab, const T& cbar,
                                                    const T& rhobar) {
    const T phi = hab * vx / (x2 + 0.01 * hab * hab);
    const T q = rhobar * (-c.linear * cbar * phi + c.quadratic * phi * phi);
    return whereNegative(vx, q);
}

}  // namespace gsph
