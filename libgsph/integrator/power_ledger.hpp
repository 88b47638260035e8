// SPDX-License-Identifier: MIT
// The energy ledger's works (particles/state.hpp, EnergyLedger) by the trapezoidal rule over each
// step, from the powers at t_n and t_{n+1}. The powers are read from what the force stages wrote
// (forces/force_stage.hpp), not from the stages:
//   viscous   Σ f_visc·v      booked as viscous work (the dissipation is −∫ P dt)
//   hourglass Σ f_hg·v        booked as hourglass work (likewise)
//   cohesive  Σ f_coh·v       booked as cohesive work (likewise: the softening bonds' take)
//   external  Σ f_ext·v + the stages' scalar external power (a moving wall's push)
//   boundary  the reactions' power at constrained particles (boundary/constraints.hpp)
#pragma once

#include <vector>

#include "boundary/constraints.hpp"
#include "forces/force_stage.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

struct LedgerPowers {
    double viscous = 0.0, hourglass = 0.0, boundary = 0.0, external = 0.0, cohesive = 0.0;  ///< [W]
};

/// The powers at the state's time and velocities: each process sums its own particles'
/// (channels.owned) exactly and channels.domain adds the processes' sums, so every power is
/// rounded once and is the same for any thread or process count. `stagePower`: Σ of the stages'
/// reported externalPower at the last force evaluation (their totals over every process).
LedgerPowers measurePowers(const Reference& ref, const State& state, const ForceChannels& channels,
                           double stagePower, const std::vector<VelocityConstraint>& constraints);

/// Stores the powers at the run's start (the first trapezoid's left end).
void startLedger(EnergyLedger& ledger, const LedgerPowers& powers);

/// Books one step of length dt ending at `powers` and keeps them for the next step.
void bookStep(EnergyLedger& ledger, const LedgerPowers& powers, double dt);

}  // namespace gsph
