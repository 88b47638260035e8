// SPDX-License-Identifier: MIT
// Internal force of the total Lagrangian form (DESIGN §4), = −∂E/∂x of E = Σ_a V_a Ψ(F(a)):
//   f_c = Σ_b [V_c ω_b P(c) g_cb − V_b ω_c P(b) g_bc] = Σ_b (ω_b K_c + ω_c K_b) ∇W_cb,
// with K = V P G and P = J σ F^{-T} (using g_ab = G(a) ∇W_ab and ∇W_bc = −∇W_cb). Each
// particle gathers from its own list only (no scatter), so the loop is thread-count-independent
// and Σ_c f_c = 0 to round-off. Artificial viscosity adds the pair pressure q_cb through
// N = V J F^{-T} G the same way; hourglass control adds central pair forces.
#pragma once

#include <vector>

#include "forces/artificial_viscosity.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// Per-particle quantities the force loop reads, derived from F and σ each step.
struct StressFactors {
    std::vector<Mat3> K;             ///< V J σ F^{-T} G
    std::vector<Mat3> N;             ///< V J F^{-T} G
    std::vector<double> soundSpeed;  ///< c [m/s]
    std::vector<double> density;     ///< ρ0/J [kg/m³]
    void resize(std::size_t n) {
        K.resize(n);
        N.resize(n);
        soundSpeed.resize(n);
        density.resize(n);
    }
};

struct ForceOptions {
    ViscosityCoefficients viscosity;
    double hourglass = 0.0;      ///< α (0 = off)
    double youngsModulus = 0.0;  ///< E of the body, scales the hourglass penalty [Pa]
};

/// Per-particle non-conservative forces, kept for the energy ledger.
struct ForceParts {
    std::vector<Vec3> viscous;
    std::vector<Vec3> hourglass;
};

/// f_c for c in [begin, end) (one body). Writes force[c]; parts.* only when that term is on.
void internalForce(const Reference& ref, const State& state, const StressFactors& factors,
                   const ForceOptions& options, Index begin, Index end, std::vector<Vec3>& force,
                   ForceParts& parts);

}  // namespace gsph
