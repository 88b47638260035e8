// SPDX-License-Identifier: MIT
// Applied loads: gravity, a body force m_a g on every particle, and forces on named
// particle sets, a total force F shared by mass, f_a = F m_a / Σ_set m (so the set accelerates
// uniformly under F alone, and Σ f_a = F exactly up to round-off). Both are constant in time,
// so they are summed once into one force per particle; the integrator adds it at every force
// evaluation and books its power Σ f_a·v_a as external work.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
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

}  // namespace gsph
