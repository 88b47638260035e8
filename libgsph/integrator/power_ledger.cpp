// SPDX-License-Identifier: MIT
#include "integrator/power_ledger.hpp"

#include "core/parallel.hpp"

namespace gsph {
namespace {

// Σ f_a·v_a over the owned particles (0 for a channel no stage uses).
double powerOf(const std::vector<Vec3>& part, ParticleRange owned, const State& state,
               std::vector<double>& partial) {
    if (part.empty()) return 0.0;
    return deterministicSum(
        owned, 0.0,
        [&](Index a) {
            return part[static_cast<std::size_t>(a)].dot(state.v[static_cast<std::size_t>(a)]);
        },
        partial);
}

}  // namespace

LedgerPowers measurePowers(const Reference& ref, const State& state, const ForceChannels& channels,
                           double stagePower, const std::vector<VelocityConstraint>& constraints,
                           std::vector<double>& partialSums) {
    LedgerPowers p;
    const ParticleRange owned = channels.owned;
    p.viscous = powerOf(channels.parts.viscous, owned, state, partialSums);
    p.hourglass = powerOf(channels.parts.hourglass, owned, state, partialSums);
    p.cohesive = powerOf(channels.parts.cohesive, owned, state, partialSums);
    p.boundary = reactionPower(constraints, ref, state, channels.force, owned);
    p.external = channels.external.empty()
                     ? stagePower
                     : stagePower + powerOf(channels.external, owned, state, partialSums);
    return p;
}

void startLedger(EnergyLedger& ledger, const LedgerPowers& powers) {
    ledger.viscousPower = powers.viscous;
    ledger.hourglassPower = powers.hourglass;
    ledger.cohesivePower = powers.cohesive;
    ledger.boundaryPower = powers.boundary;
    ledger.externalPower = powers.external;
}

void bookStep(EnergyLedger& L, const LedgerPowers& p, double dt) {
    L.externalWork += 0.5 * dt * (L.externalPower + p.external);
    L.viscousWork -= 0.5 * dt * (L.viscousPower + p.viscous);
    L.hourglassWork -= 0.5 * dt * (L.hourglassPower + p.hourglass);
    L.cohesiveWork -= 0.5 * dt * (L.cohesivePower + p.cohesive);
    L.boundaryWork += 0.5 * dt * (L.boundaryPower + p.boundary);
    startLedger(L, p);
}

}  // namespace gsph
