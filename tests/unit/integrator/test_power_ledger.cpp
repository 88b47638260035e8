// SPDX-License-Identifier: MIT
// The energy ledger's bookkeeping (integrator/power_ledger.hpp) and the reactions' power
// (boundary/constraints.hpp), against values computed by hand.
#include <gtest/gtest.h>

#include "boundary/constraints.hpp"
#include "integrator/power_ledger.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

TEST(PowerLedger, TrapezoidOverTheStep) {
    EnergyLedger L;
    startLedger(L, {2.0, -1.0, 3.0, 4.0, -3.0});
    bookStep(L, {6.0, 1.0, 5.0, 8.0, -7.0}, 0.5);
    EXPECT_EQ(L.viscousWork, -0.25 * (2.0 + 6.0));  // dissipation: −∫ P dt
    EXPECT_EQ(L.hourglassWork, -0.25 * (-1.0 + 1.0));
    EXPECT_EQ(L.cohesiveWork, 0.25 * (3.0 + 7.0));  // the cohesive forces' take: −∫ P dt
    EXPECT_EQ(L.cohesivePower, -7.0);
    EXPECT_EQ(L.boundaryWork, 0.25 * (3.0 + 5.0));
    EXPECT_EQ(L.externalWork, 0.25 * (4.0 + 8.0));
    EXPECT_EQ(L.viscousPower, 6.0);  // kept for the next step
    EXPECT_EQ(L.externalPower, 8.0);
}

TEST(PowerLedger, PowersFromTheChannelsAndTheReactions) {
    Reference ref =
        latticeReference(gradedBoxMap(Vec3(0.2, 0.1, 0.1), {}), 3, {2, 1, 1}, 1000.0, 1.2);
    ref.mass = {2.0, 3.0};  // [kg]
    const double m = ref.mass[1];
    State s = State::atRest(ref.X);
    s.time = 2.0;
    s.dt = 1e-3;
    s.v[0] = Vec3(1.0, 0.0, 0.0);
    s.v[1] = Vec3(0.0, 2.0, 0.0);
    ForceChannels c;
    c.owned = {0, ref.size()};
    c.force = {Vec3(3.0, 0.0, 0.0), Vec3(0.0, 5.0, 0.0)};
    c.parts.viscous = {Vec3(-1.0, 0.0, 0.0), Vec3(0.0, -0.5, 0.0)};
    c.external = {Vec3(0.0, 0.0, 0.0), Vec3(0.0, 7.0, 0.0)};
    // Particle 1 is driven at v = (0, t, 0): a = (0, 1, 0), its reaction is m a − f.
    const std::vector<VelocityConstraint> driven = {
        {"driven", {1}, [](double t, const Vec3&) { return Vec3(0.0, t, 0.0); }}};
    const LedgerPowers p = measurePowers(ref, s, c, 0.25, driven);
    EXPECT_EQ(p.viscous, -1.0 * 1.0 + -0.5 * 2.0);
    EXPECT_EQ(p.hourglass, 0.0) << "no stage wrote the channel";
    EXPECT_EQ(p.cohesive, 0.0) << "no stage wrote the channel";
    EXPECT_EQ(p.external, 0.25 + 7.0 * 2.0);
    EXPECT_NEAR(p.boundary, (m * 1.0 - 5.0) * 2.0, 1e-9);
    applyConstraints(driven, ref, s, 3.0);
    EXPECT_EQ(s.v[1], Vec3(0.0, 3.0, 0.0));
    EXPECT_EQ(s.v[0], Vec3(1.0, 0.0, 0.0));
}

}  // namespace
}  // namespace gsph
