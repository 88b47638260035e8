// SPDX-License-Identifier: MIT
// The pressure stage (boundary/pressure.hpp): the curve p(t), Nanson's formula f = −p cof(F) A
// for a rotated and a stretched particle, the external channel, and the refusals.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "boundary/pressure.hpp"
#include "core/error.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

Reference block() {
    return latticeReference(gradedBoxMap(Vec3(0.04, 0.01, 0.01), {}), 3, {4, 1, 1}, 7800.0, 1.2);
}

PressureLoad endFace(std::vector<std::pair<double, double>> curve) {
    // The x = 0 face of particle 0: area 1e-4 m², outward −x.
    return {"end", {0}, {Vec3(-1e-4, 0.0, 0.0)}, std::move(curve)};
}

ForceChannels channelsFor(std::size_t n) {
    ForceChannels c;
    c.force.assign(n, Vec3::Zero());
    c.external.assign(n, Vec3::Zero());
    return c;
}

TEST(Pressure, CurveIsPiecewiseLinearAndConstantOutside) {
    const PressureLoad p = endFace({{1.0, 10.0}, {3.0, 30.0}, {4.0, -2.0}});
    EXPECT_EQ(p.at(0.0), 10.0);
    EXPECT_EQ(p.at(1.0), 10.0);
    EXPECT_EQ(p.at(2.0), 20.0);
    EXPECT_EQ(p.at(3.5), 14.0);
    EXPECT_EQ(p.at(4.0), -2.0);
    EXPECT_EQ(p.at(9.0), -2.0);
    EXPECT_EQ(endFace({{0.0, 5e6}}).at(1e-3), 5e6);
}

TEST(Pressure, FollowsTheFaceAsItRotatesAndStretches) {
    const Reference ref = block();
    PressureStage stage(ref, endFace({{0.0, 2e6}}));
    State s = State::atRest(ref.X);
    // Rotated: the force turns with the face, |f| = p A.
    const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    s.F[0] = R;
    ForceChannels c = channelsFor(s.x.size());
    stage.addForces(s, c);
    const Vec3 expected = -2e6 * (R * Vec3(-1e-4, 0, 0));
    EXPECT_LT((c.force[0] - expected).norm(), 1e-15 * expected.norm());
    EXPECT_EQ(c.external[0], c.force[0]) << "its power is external work";
    for (std::size_t a = 1; a < s.x.size(); ++a) EXPECT_EQ(c.force[a], Vec3::Zero());
    // Stretched: the face's current area is λy λz A (Nanson), whatever λx.
    s.F[0] = Vec3(1.3, 0.9, 1.1).asDiagonal();
    c = channelsFor(s.x.size());
    stage.addForces(s, c);
    EXPECT_NEAR(c.force[0][0], 2e6 * 1e-4 * 0.9 * 1.1, 1e-12);
    EXPECT_EQ(c.force[0][1], 0.0);
    EXPECT_EQ(c.force[0][2], 0.0);
}

TEST(Pressure, RefusesBadLoads) {
    const Reference ref = block();
    EXPECT_THROW(PressureStage(ref, endFace({})), InputError);
    EXPECT_THROW(PressureStage(ref, endFace({{1.0, 1.0}, {1.0, 2.0}})), InputError);
    PressureLoad wrongAreas = endFace({{0.0, 1.0}});
    wrongAreas.area.push_back(Vec3::Zero());
    EXPECT_THROW(PressureStage(ref, wrongAreas), InputError);
    PressureLoad outside = endFace({{0.0, 1.0}});
    outside.particles = {99};
    EXPECT_THROW(PressureStage(ref, outside), InputError);
}

}  // namespace
}  // namespace gsph
