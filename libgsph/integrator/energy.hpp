// SPDX-License-Identifier: MIT
// Energy and momentum of a run, for the history and the conservation tests.
//   kinetic = Σ ½ m |v|²;  elastic = Σ V_a J_a ψ(σ_a, history_a) (ψ: the material's stored
//   energy per current volume, V_a the quadrature volume of DESIGN §4); plastic work = Σ of
//   the particles' (State::plasticWork); the ledger's other works (integrated by the
//   integrator); the contact springs' potential. Balance:
//   kinetic + elastic + viscous + hourglass + plastic + damage + fracture + cohesive + contact
//   − boundary − external = const.
// Kinetic, elastic and plastic energy and momentum are summed body by body, each an exactly
// rounded sum (core/exact_sum.hpp) over the particles and, in a split run, over the processes
// (each its own particles: no gather), so they do not depend on the thread or process count;
// the run's are the sums of the bodies' in body order: the bodies' shares add up to the run's
// exactly.
#pragma once

#include <vector>

#include "integrator/velocity_verlet.hpp"

namespace gsph {

/// One body's share of the run's per-particle energies and momentum.
struct BodyEnergy {
    double kinetic = 0.0;
    double elastic = 0.0;
    double plasticWork = 0.0;
    Vec3 momentum = Vec3::Zero();
};

struct EnergyReport {
    double kinetic = 0.0;
    double elastic = 0.0;
    double viscousWork = 0.0;        ///< energy taken by artificial viscosity
    double hourglassWork = 0.0;      ///< energy taken by the hourglass control
    double boundaryWork = 0.0;       ///< work done on the bodies by prescribed velocities
    double plasticWork = 0.0;        ///< dissipated by plastic flow
    double damageDissipation = 0.0;  ///< elastic energy lost by failing particles
    double fractureEnergy = 0.0;     ///< elastic energy released by brittle bond failure
    double cohesiveWork = 0.0;       ///< taken by the cohesive forces of softening bonds
    double contactEnergy = 0.0;      ///< potential of the penalty springs (bodies, walls)
    double externalWork = 0.0;       ///< work of gravity, set forces and walls on the bodies
    Vec3 momentum = Vec3::Zero();
    /// Per body, in body order: kinetic, elastic, plastic work, momentum sum to the above.
    std::vector<BodyEnergy> bodies;
    /// Conserved total: kinetic + elastic + viscous + hourglass + plastic + damage + fracture
    /// + cohesive + contact − boundary − external.
    double total() const {
        return kinetic + elastic + viscousWork + hourglassWork + plasticWork + damageDissipation +
               fractureEnergy + cohesiveWork + contactEnergy - boundaryWork - externalWork;
    }
};

/// Over every body and every particle.
EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies);
/// Over the `owned` particles and, with a `domain` (a split run; collective), every process's.
EnergyReport measureEnergy(const Reference& ref, const State& state,
                           const std::vector<BodyRange>& bodies, ParticleRange owned,
                           Domain* domain);

}  // namespace gsph
