// SPDX-License-Identifier: MIT
// The energy report's bodies (integrator/energy.hpp): a Johnson–Cook copper block struck at
// 80 m/s by an elastic steel block (contact between bodies, plastic flow in the copper). The
// bodies' kinetic, elastic and plastic energies and momenta add up to the run's exactly, in
// body order; each body's share is the sum over its own particles (against a plain loop), the
// elastic striker has no plastic work, and the plastic work is the particles' sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "simulation.hpp"
#include "support/contact_fixtures.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

using testing::Box;

TEST(EnergyReport, BodiesAddUpToTheRunExactly) {
    SolverOptions options;
    options.viscosity = {1.0, 1.0};
    options.hourglass = 0.1;
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    Simulation sim(
        testing::boxBodies({Box{Vec3::Zero(), Vec3(0.012, 0.012, 0.006), {8, 8, 4}, 8960.0},
                            Box{Vec3(0.003, 0.003, 0.0062), Vec3(0.006, 0.006, 0.006), {4, 4, 4}}}),
        {testing::withLinearEos(testing::kCopperElastic, testing::copperParams()),
         HypoElastic(steel)},
        options);
    const Reference& ref = sim.reference();
    std::vector<Vec3> v(static_cast<std::size_t>(ref.size()), Vec3::Zero());
    for (std::size_t a = 0; a < v.size(); ++a)
        if (ref.body[a] == 1) v[a] = Vec3(5.0, -3.0, -80.0);
    sim.setVelocities(v);
    for (int i = 0; i < 150; ++i) sim.step();

    const EnergyReport e = sim.energy();
    ASSERT_EQ(e.bodies.size(), 2u);
    const BodyEnergy &plate = e.bodies[0], &striker = e.bodies[1];
    std::printf(
        "kinetic %.6e = %.6e + %.6e J, elastic %.6e = %.6e + %.6e J, plastic %.6e = %.6e + "
        "%.6e J, momentum z %.6e = %.6e + %.6e kg m/s\n",
        e.kinetic, plate.kinetic, striker.kinetic, e.elastic, plate.elastic, striker.elastic,
        e.plasticWork, plate.plasticWork, striker.plasticWork, e.momentum[2], plate.momentum[2],
        striker.momentum[2]);
    // Exact identities: the run's values are the bodies' sums in body order.
    EXPECT_EQ(e.kinetic, 0.0 + plate.kinetic + striker.kinetic);
    EXPECT_EQ(e.elastic, 0.0 + plate.elastic + striker.elastic);
    EXPECT_EQ(e.plasticWork, 0.0 + plate.plasticWork + striker.plasticWork);
    for (int d = 0; d < 3; ++d)
        EXPECT_EQ(e.momentum[d], 0.0 + plate.momentum[d] + striker.momentum[d]) << d;

    // The striker met the plate and the plate flowed; the elastic striker dissipates nothing.
    EXPECT_GT(plate.plasticWork, 1e-3 * striker.kinetic);
    EXPECT_EQ(striker.plasticWork, 0.0);
    EXPECT_LT(plate.momentum[2], 0.0);

    // Each body's share against a plain loop over its particles (another summation order).
    const State& s = sim.state();
    for (std::size_t b = 0; b < 2; ++b) {
        const BodyRange& range = sim.bodies()[b];
        double kinetic = 0.0, plastic = 0.0;
        Vec3 momentum = Vec3::Zero();
        for (Index a = range.begin; a < range.end; ++a) {
            const auto ia = static_cast<std::size_t>(a);
            kinetic += 0.5 * ref.mass[ia] * s.v[ia].squaredNorm();
            momentum += ref.mass[ia] * s.v[ia];
            plastic += s.plasticWork[ia];
        }
        const BodyEnergy& got = e.bodies[b];
        EXPECT_NEAR(got.kinetic, kinetic, 1e-13 * kinetic) << b;
        EXPECT_NEAR(got.plasticWork, plastic, 1e-13 * plastic) << b;
        EXPECT_LT((got.momentum - momentum).norm(), 1e-13 * momentum.norm()) << b;
    }
}

}  // namespace
}  // namespace gsph
