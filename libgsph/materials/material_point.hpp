// SPDX-License-Identifier: MIT
// What a strength model sees of one particle during a step (DESIGN §5), and the copies between
// it and the State. Every model reads and writes σ and the current density; a model with
// history variables names them in `kHistory` (its descriptor: each variable's field, so its
// name and unit, where the State keeps it and where the point carries it), and the integrator
// copies exactly those in and out around the update: the elastic path (no history) pays
// nothing. Models also report what the update dissipated.
#pragma once

#include <array>
#include <cstddef>

#include "core/types.hpp"
#include "particles/fields.hpp"
#include "particles/state.hpp"

namespace gsph {

struct MaterialPoint {
    Mat3 cauchy = Mat3::Zero();  ///< in: σ_n; out: σ_{n+1} [Pa]
    double density = 0.0;        ///< current density ρ0/J at t_{n+1} [kg/m³]
    // History (in: t_n, out: t_{n+1}); models without history leave it alone.
    double plasticStrain = 0.0;                    ///< effective plastic strain ε̄p
    double temperature = State::kRoomTemperature;  ///< T [K]
    double damage = 0.0;                           ///< Johnson–Cook damage D ∈ [0, 1]
    double internalEnergy = 0.0;                   ///< specific internal energy e [J/kg]
    double damageDriver = 0.0;  ///< ω = Σ Δε̄p/εf of a nonlocal damage (D is its average)
    /// In only: the nonlocal average ω̄ of the drivers at t_n (failure/nonlocal_damage.hpp);
    /// read by models with nonlocal damage, D = min(1, max(D, ω̄)).
    double averagedDriver = 0.0;
    /// In only: the particle's size h, its smallest reference spacing [m] (0: a material point
    /// without a particle); read by damage with a reference size (JohnsonCookDamage).
    double size = 0.0;
    // What this update dissipated, per unit current volume [J/m³] (out only).
    double plasticWork = 0.0;        ///< Δw_p
    double damageDissipation = 0.0;  ///< elastic energy lost when the point failed (D reached 1)
};

/// A history variable of a material model: its field (name, unit: particles/fields.hpp), the
/// State's array of it and the MaterialPoint's member that carries it through an update.
struct HistoryVariable {
    const Field* field;
    std::vector<double> State::*array;
    double MaterialPoint::*point;
};

namespace history {
inline constexpr HistoryVariable kPlasticStrain{&fields::kPlasticStrain, &State::plasticStrain,
                                                &MaterialPoint::plasticStrain};
inline constexpr HistoryVariable kTemperature{&fields::kTemperature, &State::temperature,
                                              &MaterialPoint::temperature};
inline constexpr HistoryVariable kDamage{&fields::kDamage, &State::damage, &MaterialPoint::damage};
inline constexpr HistoryVariable kInternalEnergy{&fields::kInternalEnergy, &State::internalEnergy,
                                                 &MaterialPoint::internalEnergy};
inline constexpr HistoryVariable kDamageDriver{&fields::kDamageDriver, &State::damageDriver,
                                               &MaterialPoint::damageDriver};
}  // namespace history

/// The history of particle a from the state: Model::kHistory's variables.
template <class Model>
inline void loadHistory(const State& s, std::size_t a, MaterialPoint& p) {
    for (const HistoryVariable& h : Model::kHistory) p.*(h.point) = (s.*(h.array))[a];
}

/// The history of particle a back into the state.
template <class Model>
inline void storeHistory(const MaterialPoint& p, std::size_t a, State& s) {
    for (const HistoryVariable& h : Model::kHistory) (s.*(h.array))[a] = p.*(h.point);
}

/// True for a model with history variables.
template <class Model>
inline constexpr bool kHasHistory = !Model::kHistory.empty();

}  // namespace gsph
