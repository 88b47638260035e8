// SPDX-License-Identifier: MIT
#include "integrator/energy.hpp"

#include <Eigen/LU>
#include <type_traits>

#include "core/parallel.hpp"

namespace gsph {

EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies) {
    EnergyReport e;
    e.kinetic = deterministicSum(ref.size(), 0.0, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        return 0.5 * ref.mass[ia] * state.v[ia].squaredNorm();
    });
    e.momentum = deterministicSum(ref.size(), Vec3(Vec3::Zero()), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        return Vec3(ref.mass[ia] * state.v[ia]);
    });
    for (const BodyRange& body : bodies) {
        e.elastic += std::visit(
            [&](const auto& model) {
                using Model = std::decay_t<decltype(model)>;
                return deterministicSum(body.end - body.begin, 0.0, [&](Index i) {
                    const auto ia = static_cast<std::size_t>(body.begin + i);
                    const double J = state.F[ia].determinant();
                    MaterialPoint point;
                    point.cauchy = state.cauchy[ia];
                    point.density = model.elastic().density / J;
                    if constexpr (Model::kTracksHistory) loadHistory(state, ia, point);
                    return ref.quadVolume[ia] * J * model.storedEnergyDensity(point);
                });
            },
            *body.material);
    }
    e.viscousWork = state.ledger.viscousWork;
    e.hourglassWork = state.ledger.hourglassWork;
    e.boundaryWork = state.ledger.boundaryWork;
    e.plasticWork = state.ledger.plasticWork;
    e.damageDissipation = state.ledger.damageDissipation;
    e.fractureEnergy = state.ledger.fractureEnergy;
    e.contactEnergy = state.ledger.contactEnergy;
    e.externalWork = state.ledger.externalWork;
    return e;
}

}  // namespace gsph
