// SPDX-License-Identifier: MIT
#include "integrator/energy.hpp"

#include <Eigen/LU>
#include <type_traits>

#include "core/parallel.hpp"

namespace gsph {
namespace {

BodyEnergy measureBody(const Reference& ref, const State& state, const BodyRange& body,
                       std::vector<double>& partial, std::vector<Vec3>& partialVec) {
    BodyEnergy e;
    e.kinetic = sumOverBody(
        body, 0.0,
        [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            return 0.5 * ref.mass[ia] * state.v[ia].squaredNorm();
        },
        partial);
    e.momentum = sumOverBody(
        body, Vec3(Vec3::Zero()),
        [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            return Vec3(ref.mass[ia] * state.v[ia]);
        },
        partialVec);
    e.elastic = std::visit(
        [&](const auto& model) {
            using Model = std::decay_t<decltype(model)>;
            return sumOverBody(
                body, 0.0,
                [&](Index a) {
                    const auto ia = static_cast<std::size_t>(a);
                    const double J = state.F[ia].determinant();
                    MaterialPoint point;
                    point.cauchy = state.cauchy[ia];
                    point.density = model.elastic().density / J;
                    if constexpr (kHasHistory<Model>) loadHistory<Model>(state, ia, point);
                    return ref.quadVolume[ia] * J * model.storedEnergyDensity(point);
                },
                partial);
        },
        *body.material);
    e.plasticWork = sumOverBody(
        body, 0.0, [&](Index a) { return state.plasticWork[static_cast<std::size_t>(a)]; },
        partial);
    return e;
}

}  // namespace

EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies) {
    EnergyReport e;
    std::vector<double> partial;
    std::vector<Vec3> partialVec;
    e.bodies.reserve(bodies.size());
    for (const BodyRange& body : bodies) {
        const BodyEnergy& b =
            e.bodies.emplace_back(measureBody(ref, state, body, partial, partialVec));
        e.kinetic += b.kinetic;
        e.elastic += b.elastic;
        e.plasticWork += b.plasticWork;
        e.momentum += b.momentum;
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
