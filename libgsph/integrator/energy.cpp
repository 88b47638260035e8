// SPDX-License-Identifier: MIT
#include "integrator/energy.hpp"

#include <Eigen/LU>
#include <type_traits>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// A body's sums over its particles in `owned`: kinetic, elastic, plastic work, momentum x, y, z.
constexpr std::size_t kBodySums = 6;

void sumBody(const Reference& ref, const State& state, const BodyRange& body, ParticleRange owned,
             ExactSum* sums) {
    const ParticleRange mine = owned.within(body.begin, body.end);
    const auto mass = [&](Index a) { return ref.mass[static_cast<std::size_t>(a)]; };
    const auto v = [&](Index a) -> const Vec3& { return state.v[static_cast<std::size_t>(a)]; };
    sums[0] = exactSum(mine, [&](Index a) { return 0.5 * mass(a) * v(a).squaredNorm(); });
    sums[1] = std::visit(
        [&](const auto& model) {
            using Model = std::decay_t<decltype(model)>;
            return exactSum(mine, [&](Index a) {
                const auto ia = static_cast<std::size_t>(a);
                const double J = state.F[ia].determinant();
                MaterialPoint point;
                point.cauchy = state.cauchy[ia];
                point.density = model.elastic().density / J;
                if constexpr (kHasHistory<Model>) loadHistory<Model>(state, ia, point);
                return ref.quadVolume[ia] * J * model.storedEnergyDensity(point);
            });
        },
        *body.material);
    sums[2] =
        exactSum(mine, [&](Index a) { return state.plasticWork[static_cast<std::size_t>(a)]; });
    for (int d = 0; d < 3; ++d)
        sums[3 + static_cast<std::size_t>(d)] =
            exactSum(mine, [&](Index a) { return mass(a) * v(a)[d]; });
}

}  // namespace

EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies) {
    return measureEnergy(ref, state, bodies, ParticleRange{0, ref.size()}, nullptr);
}

EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies, ParticleRange owned,
                           Domain* domain) {
    std::vector<ExactSum> sums(kBodySums * bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b)
        sumBody(ref, state, bodies[b], owned, &sums[kBodySums * b]);
    if (domain) domain->sum(sums);
    EnergyReport e;
    e.bodies.reserve(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const ExactSum* s = &sums[kBodySums * b];
        const BodyEnergy& body = e.bodies.emplace_back(
            BodyEnergy{.kinetic = s[0].value(),
                       .elastic = s[1].value(),
                       .plasticWork = s[2].value(),
                       .momentum = Vec3(s[3].value(), s[4].value(), s[5].value())});
        e.kinetic += body.kinetic;
        e.elastic += body.elastic;
        e.plasticWork += body.plasticWork;
        e.momentum += body.momentum;
    }
    e.viscousWork = state.ledger.viscousWork;
    e.hourglassWork = state.ledger.hourglassWork;
    e.boundaryWork = state.ledger.boundaryWork;
    e.damageDissipation = state.ledger.damageDissipation;
    e.fractureEnergy = state.ledger.fractureEnergy;
    e.cohesiveWork = state.ledger.cohesiveWork;
    e.contactEnergy = state.ledger.contactEnergy;
    e.externalWork = state.ledger.externalWork;
    return e;
}

}  // namespace gsph
