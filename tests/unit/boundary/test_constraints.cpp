// SPDX-License-Identifier: MIT
// Velocity constraints (boundary/constraints.hpp): a constraint sets only the components it
// holds, and the reactions' power counts only those.
#include <gtest/gtest.h>

#include "boundary/constraints.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

TEST(Constraints, HoldsOnlyItsComponents) {
    Reference ref =
        latticeReference(gradedBoxMap(Vec3(0.04, 0.01, 0.01), {}), 3, {4, 1, 1}, 7800.0, 1.2);
    ref.mass.assign(4, 0.03);  // the reactions need masses only
    State state = State::atRest(ref.X);
    for (Vec3& v : state.v) v = Vec3(1.0, 2.0, 3.0);
    const VelocityConstraint roller{"roller", {0, 1}, {}, {false, true, false}};
    const VelocityConstraint driven{"driven",
                                    {3},
                                    [](double t, const Vec3&) { return Vec3(10.0 * t, 5.0, 6.0); },
                                    {true, false, true}};
    applyConstraints({roller, driven}, ref, state, 0.5);
    EXPECT_EQ(state.v[0], Vec3(1.0, 0.0, 3.0));
    EXPECT_EQ(state.v[1], Vec3(1.0, 0.0, 3.0));
    EXPECT_EQ(state.v[2], Vec3(1.0, 2.0, 3.0)) << "not constrained";
    EXPECT_EQ(state.v[3], Vec3(5.0, 2.0, 6.0));
    // Power of the driven set's reaction on its held components only: (m·10 − f_x) v_x +
    // (0 − f_z) v_z; the free y component (force 7, velocity 2) does no reaction work.
    state.time = 0.5;
    state.dt = 1e-3;
    std::vector<Vec3> force(4, Vec3::Zero());
    force[3] = Vec3(1.0, 7.0, 2.0);
    const double m = ref.mass[3];
    EXPECT_NEAR(reactionPower({roller, driven}, ref, state, force, {0, ref.size()}).value(),
                (m * 10.0 - 1.0) * 5.0 + (0.0 - 2.0) * 6.0, 1e-9 * m * 50.0);
}

}  // namespace
}  // namespace gsph
