// SPDX-License-Identifier: MIT
// Applied loads: gravity, a body force m_a g on every particle, and forces on named
// particle sets, a total force F shared by mass, f_a = F m_a / Σ_set m (so the set accelerates
// uniformly under F alone, and Σ f_a = F exactly up to round-off). Both are constant in time,
// so they are summed once into one force per particle; ConstantLoadStage adds it at every force
// evaluation, to the external channel too, so its power Σ f_a·v_a is booked as external work
// (forces/force_stage.hpp).
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "forces/force_stage.hpp"
#include "particles/reference.hpp"

namespace gsph {

struct SetForce {
    std::string name;  ///< the particle set's name (for messages)
    std::vector<Index> particles;
    Vec3 total = Vec3::Zero();  ///< F [N] (per metre of thickness in 2-D)
};

struct Loads {
    Vec3 gravity = Vec3::Zero();  ///< g [m/s²]
    std::vector<SetForce> setForces;

    bool empty() const { return gravity.isZero(0.0) && setForces.empty(); }
};

/// The constant load of every particle: m_a g + Σ over the force sets holding a of F m_a/M_set.
/// Throws InputError on an empty set or a particle index out of range.
std::vector<Vec3> loadPerParticle(const Reference& ref, const Loads& loads);

class ConstantLoadStage final : public ForceStage {
  public:
    /// Throws as loadPerParticle.
    ConstantLoadStage(const Reference& ref, const Loads& loads)
        : load_(loadPerParticle(ref, loads)) {}
    std::string name() const override { return "gravity and set forces"; }
    StageNeeds needs() const override { return {.external = true}; }
    StageReport addForces(const State& state, ForceChannels& out) override;

  private:
    std::vector<Vec3> load_;
};

}  // namespace gsph
