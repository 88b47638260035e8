// SPDX-License-Identifier: MIT
// What a strength model sees of one particle during a step (DESIGN §5), and the copies between
// it and the State. Every model reads and writes σ and the current density; models with a
// history (Model::kTracksHistory, e.g. Johnson–Cook) also read and write ε̄p, T, D and the
// specific internal energy, and report what the update dissipated. The integrator copies the
// history only for such models, so the elastic path pays nothing for it.
#pragma once

#include <cstddef>

#include "core/types.hpp"
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
    // What this update dissipated, per unit current volume [J/m³] (out only).
    double plasticWork = 0.0;        ///< Δw_p
    double damageDissipation = 0.0;  ///< elastic energy lost when the point failed (D reached 1)
};

/// The history of particle a from the state.
inline void loadHistory(const State& s, std::size_t a, MaterialPoint& p) {
    p.plasticStrain = s.plasticStrain[a];
    p.temperature = s.temperature[a];
    p.damage = s.damage[a];
    p.internalEnergy = s.internalEnergy[a];
}

/// The history of particle a back into the state.
inline void storeHistory(const MaterialPoint& p, std::size_t a, State& s) {
    s.plasticStrain[a] = p.plasticStrain;
    s.temperature[a] = p.temperature;
    s.damage[a] = p.damage;
    s.internalEnergy[a] = p.internalEnergy;
}

}  // namespace gsph
