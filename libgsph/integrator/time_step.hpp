// SPDX-License-Identifier: MIT
// Step 7 of Algorithm 1 (DESIGN §4), the stable time step:
//   Δt_{n+1} = CFL · min_a ℓ_a/(c_a + |v_a|),  ℓ_a the particle's current spacing
// (integrator/stress_update.hpp); a particle on stiff springs (the frequency channel of the
// force stages, forces/force_stage.hpp: contact) takes CFL / √(((c_a + |v_a|)/ℓ_a)² + ω_a²/4).
// The rule reads what the stages wrote, never the stages themselves.
#pragma once

#include <vector>

#include "distributed/domain.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

struct TimeStepRule {
    double cfl = 0.3;            ///< Courant number
    double fixedTimeStep = 0.0;  ///< > 0: this Δt instead of the CFL estimate
    /// > 0: a stable Δt below this fraction of State::initialDt stops the run (0: only Δt ≤ 0
    /// or NaN).
    double minTimeStepRatio = 0.0;
};

/// The next Δt: the minimum over the `owned` particles, then over the domain's processes.
/// `frequency2`: ω_a² per particle, or empty. Throws NumericalError naming the particle that
/// limits Δt when it is not finite, ≤ 0 or below the rule's floor (on the process that owns
/// it; the others throw without a particle).
double stableTimeStep(const Reference& ref, const State& state, const TimeStepRule& rule,
                      const std::vector<double>& lengthScale, const std::vector<double>& soundSpeed,
                      const std::vector<double>& frequency2, ParticleRange owned, Domain& domain);

}  // namespace gsph
