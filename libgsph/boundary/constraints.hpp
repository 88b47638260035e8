// SPDX-License-Identifier: MIT
// Kinematic boundary conditions on particle sets: fixed (v = 0) and prescribed velocity
// v = v(t, X). The integrator applies them after every kick, so a constrained particle moves
// exactly with its prescribed velocity; the force it needed is the reaction, whose power the
// energy ledger books as boundary work.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace gsph {

struct VelocityConstraint {
    std::string name;  ///< for messages (the particle set's name)
    std::vector<Index> particles;
    /// v(t, X); empty = fixed (v = 0).
    std::function<Vec3(double t, const Vec3& X)> velocity;

    Vec3 at(double t, const Vec3& X) const { return velocity ? velocity(t, X) : Vec3::Zero(); }
};

}  // namespace gsph
