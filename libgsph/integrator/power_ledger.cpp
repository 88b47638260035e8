// SPDX-License-Identifier: MIT
#include "integrator/power_ledger.hpp"

#include <array>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// Σ f_a·v_a over the owned particles (0 for a channel no stage uses).
ExactSum powerOf(const std::vector<Vec3>& part, ParticleRange owned, const State& state) {
    if (part.empty()) return {};
    return exactSum(owned, [&](Index a) {
        return part[static_cast<std::size_t>(a)].dot(state.v[static_cast<std::size_t>(a)]);
    });
}

}  // namespace

LedgerPowers measurePowers(const Reference& ref, const State& state, const ForceChannels& channels,
                           double stagePower, const std::vector<VelocityConstraint>& constraints) {
    const ParticleRange owned = channels.owned;
    std::array<ExactSum, 5> sums = {
        powerOf(channels.parts.viscous, owned, state),
        powerOf(channels.parts.hourglass, owned, state),
        powerOf(channels.parts.cohesive, owned, state),
        reactionPower(constraints, ref, state, channels.force, owned),
        powerOf(channels.external, owned, state),
    };
    if (channels.domain) channels.domain->sum(sums);
    sums[4].add(stagePower);  // already the total over the processes
    return {.viscous = sums[0].value(),
            .hourglass = sums[1].value(),
            .boundary = sums[3].value(),
            .external = sums[4].value(),
            .cohesive = sums[2].value()};
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
