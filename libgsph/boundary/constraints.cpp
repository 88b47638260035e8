// SPDX-License-Identifier: MIT
#include "boundary/constraints.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace gsph {

void checkConstraints(const std::vector<VelocityConstraint>& constraints, const Reference& ref) {
    for (const VelocityConstraint& c : constraints)
        for (Index a : c.particles)
            if (a < 0 || a >= ref.size())
                throw InputError("constraint '" + c.name + "' names particle " + std::to_string(a) +
                                 " outside [0, " + std::to_string(ref.size()) + ")");
}

void applyConstraints(const std::vector<VelocityConstraint>& constraints, const Reference& ref,
                      State& state, double t) {
    for (const VelocityConstraint& c : constraints)
        for (Index a : c.particles) {
            const auto ia = static_cast<std::size_t>(a);
            const Vec3 v = c.at(t, ref.X[ia]);
            for (int r = 0; r < 3; ++r)
                if (c.holds[static_cast<std::size_t>(r)]) state.v[ia][r] = v[r];
        }
}

ExactSum reactionPower(const std::vector<VelocityConstraint>& constraints, const Reference& ref,
                       const State& state, const std::vector<Vec3>& force, ParticleRange owned) {
    ExactSum power;
    const double eps = std::max(state.dt, 1e-12) * 1e-3;
    for (const VelocityConstraint& c : constraints) {
        if (!c.velocity) continue;  // fixed: no power
        for (Index a : c.particles) {
            if (!owned.contains(a)) continue;
            const auto ia = static_cast<std::size_t>(a);
            const Vec3 accel =
                (c.at(state.time + eps, ref.X[ia]) - c.at(state.time - eps, ref.X[ia])) / (2 * eps);
            Vec3 reaction = ref.mass[ia] * accel - force[ia];
            for (int r = 0; r < 3; ++r)
                if (!c.holds[static_cast<std::size_t>(r)]) reaction[r] = 0.0;
            power.add(reaction.dot(state.v[ia]));
        }
    }
    return power;
}

}  // namespace gsph
