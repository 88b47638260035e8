// SPDX-License-Identifier: MIT
// The stable time step (integrator/time_step.hpp): CFL · min ℓ/(c + |v|), the contact springs'
// frequency in parallel, a fixed step, and the collapse guard naming the particle.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "integrator/time_step.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

struct Fixture {
    Reference ref =
        latticeReference(gradedBoxMap(Vec3(0.3, 0.1, 0.1), {}), 3, {3, 1, 1}, 7800.0, 1.2);
    State state = State::atRest(ref.X);
    std::vector<double> length{1e-3, 2e-3, 3e-3}, speed{5000.0, 5000.0, 5000.0};
    Domain serial;
    ParticleRange all() const { return {0, ref.size()}; }
};

TEST(TimeStep, CourantOfTheSmallestRatio) {
    Fixture f;
    f.length[1] = 1.5e-3;
    f.state.v[1] = Vec3(0.0, 3000.0, 4000.0);  // |v| = 5000: ℓ/(c + |v|) = 1.5e-3/1e4, the least
    const TimeStepRule rule{0.3, 0.0, 0.0};
    EXPECT_DOUBLE_EQ(stableTimeStep(f.ref, f.state, rule, f.length, f.speed, {}, f.all(), f.serial),
                     0.3 * (1.5e-3 / 1e4));
}

TEST(TimeStep, ContactSpringsInParallel) {
    Fixture f;
    // Particle 0: wave ratio 1e-3/5000 = 2e-7; with ω² = 4e14, 1/√(1/(2e-7)² + 1e14) = 1/√(3.5e13).
    std::vector<double> omega2{4e14, 0.0, 0.0};
    const TimeStepRule rule{0.5, 0.0, 0.0};
    EXPECT_NEAR(stableTimeStep(f.ref, f.state, rule, f.length, f.speed, omega2, f.all(), f.serial),
                0.5 / std::sqrt(2.5e13 + 1e14), 1e-22);
}

TEST(TimeStep, FixedStepAndTheCollapseGuard) {
    Fixture f;
    EXPECT_EQ(
        stableTimeStep(f.ref, f.state, {0.3, 1e-9, 0.0}, f.length, f.speed, {}, f.all(), f.serial),
        1e-9);
    f.state.initialDt = 1e-6;  // the floor 1e-3 × 1e-6 = 1e-9 lies above 0.3 × 2e-7 / 100
    f.length[2] = 1e-6;
    try {
        stableTimeStep(f.ref, f.state, {0.3, 0.0, 1e-3}, f.length, f.speed, {}, f.all(), f.serial);
        FAIL() << "a collapsed step must throw";
    } catch (const NumericalError& e) {
        EXPECT_NE(std::string(e.what()).find("time step collapsed"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("particle 2 at X"), std::string::npos) << e.what();
    }
    // A NaN velocity is named, not passed over by the minimum.
    f.state.v[1] = Vec3(std::nan(""), 0.0, 0.0);
    try {
        stableTimeStep(f.ref, f.state, {0.3, 0.0, 0.0}, f.length, f.speed, {}, f.all(), f.serial);
        FAIL() << "a NaN velocity must throw";
    } catch (const NumericalError& e) {
        EXPECT_NE(std::string(e.what()).find("particle 1 at X"), std::string::npos) << e.what();
    }
    f.state.v[1] = Vec3::Zero();
    f.length.assign(3, 0.0);  // no spacing left: Δt = 0
    EXPECT_THROW(
        stableTimeStep(f.ref, f.state, {0.3, 0.0, 0.0}, f.length, f.speed, {}, f.all(), f.serial),
        NumericalError);
}

}  // namespace
}  // namespace gsph
