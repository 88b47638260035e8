// SPDX-License-Identifier: MIT
// Kinematic boundary conditions on particle sets: fixed (v = 0) and prescribed velocity
// v = v(t, X), on all three components or on some (a symmetry plane or roller holds the normal
// component at zero and leaves the others free). The integrator applies the list after every kick,
// so a constrained particle moves exactly with its prescribed velocity; the force it needed is the
// reaction, whose power the energy ledger books as boundary work (reactionPower).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/types.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

struct VelocityConstraint {
    std::string name;  ///< for messages (the particle set's name)
    std::vector<Index> particles;
    /// v(t, X); empty = fixed (v = 0).
    std::function<Vec3(double t, const Vec3& X)> velocity;
    /// The components (x, y, z) the constraint prescribes; the others stay free.
    std::array<bool, 3> holds = {true, true, true};

    Vec3 at(double t, const Vec3& X) const { return velocity ? velocity(t, X) : Vec3::Zero(); }
};

/// Throws InputError naming the constraint if it names a particle outside `ref`.
void checkConstraints(const std::vector<VelocityConstraint>& constraints, const Reference& ref);

/// v_a = v(t, X_a) on the held components of every constrained particle, in the order of the
/// list (a particle in several sets takes the last one's velocity on each component).
void applyConstraints(const std::vector<VelocityConstraint>& constraints, const Reference& ref,
                      State& state, double t);

/// Power of the reactions that keep the constrained particles on their prescribed velocity at
/// state.time: Σ (m a_prescribed − f)·v over the held components, a_prescribed by a central
/// difference of the prescription, `force` the particles' total force [W]. Fixed sets do no
/// work. Over the `owned` particles only (this process's share; all of them in a serial run),
/// summed exactly (core/exact_sum.hpp) so that the processes' shares add up to the same bits.
ExactSum reactionPower(const std::vector<VelocityConstraint>& constraints, const Reference& ref,
                       const State& state, const std::vector<Vec3>& force, ParticleRange owned);

}  // namespace gsph
