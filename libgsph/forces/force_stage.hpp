// SPDX-License-Identifier: MIT
// A force stage: one term of step 5 of Algorithm 1 (DESIGN §4), a_{n+1} = f(x_{n+1}, σ_{n+1},
// v_{n+½}) / m with f the sum of the stages' forces, added in the order the stages were composed
// (the internal force first; integrator/velocity_verlet.hpp). A stage writes into the
// ForceChannels, and the energy ledger and the time-step rule read the channels, never the
// stages: a new force term is one stage, and its energy is booked by what it writes.
//   force      every stage adds its force on each particle [N]
//   viscous,   the parts of the internal force that artificial viscosity and hourglass control
//   hourglass  contribute (their power Σ f·v is booked as viscous and hourglass work)
//   cohesive   the forces of softening bonds (forces/cohesive_bonds.hpp): −Σ f·v is their work
//   external   forces from outside the bodies (loads, wall friction): Σ f·v is external work
//   frequency2 ω_a² of stiff springs (contact) that the stable time step must resolve [1/s²]
// A channel other than `force` is sized only when a stage asks for it (needs()); a stage writes
// only its own particles' entries (gather, no scatter between threads), so the result is
// independent of the thread count.
#pragma once

#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/types.hpp"
#include "distributed/domain.hpp"
#include "particles/state.hpp"

namespace gsph {

/// Per-particle non-conservative parts of the internal force, kept for the energy ledger.
struct ForceParts {
    std::vector<Vec3> viscous;
    std::vector<Vec3> hourglass;
    std::vector<Vec3> cohesive;
};

struct ForceChannels {
    /// The particles whose entries this process's stages must write and sum (all of them in a
    /// serial run; distributed/domain.hpp). A stage may write others' entries too: nothing reads
    /// them.
    ParticleRange owned;
    /// The split (distributed/domain.hpp), for a stage that must share what its own particles
    /// found with the other processes; null in a serial run.
    Domain* domain = nullptr;
    std::vector<Vec3> force;
    ForceParts parts;  ///< viscous, hourglass, cohesive
    std::vector<Vec3> external;
    std::vector<double> frequency2;
};

/// The channels a stage writes beyond `force`.
struct StageNeeds {
    bool viscous = false, hourglass = false, cohesive = false, external = false, frequency2 = false;
};

/// What a stage reports of one force evaluation besides its forces: totals over every process of
/// a split run (a stage sums its own particles' exactly and its ForceChannels::domain adds the
/// processes', so they do not depend on the split).
struct StageReport {
    double potential = 0.0;  ///< energy stored in its springs at x_{n+1} (contact energy) [J]
    /// Power it puts into the bodies that Σ external·v does not hold (a moving wall's push) [W].
    double externalPower = 0.0;
};

class ForceStage {
  public:
    virtual ~ForceStage() = default;
    /// For timers and messages.
    virtual std::string name() const = 0;
    virtual StageNeeds needs() const { return {}; }
    /// Adds this term's forces at state.x (x_{n+1}), state.time (t_{n+1}) and state.v (v_{n+½};
    /// v_0 at the first evaluation) to the channels. Stages run one after the other, each in
    /// parallel over particles.
    virtual StageReport addForces(const State& state, ForceChannels& out) = 0;
    /// After every stage has added its forces: stores what the State keeps of this term (the
    /// walls' totals for the history), so a restart reports what the straight run did.
    virtual void record(State& /*state*/) const {}
};

}  // namespace gsph
