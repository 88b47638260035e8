// SPDX-License-Identifier: MIT
// Results do not depend on the thread count (DESIGN §9): every loop gathers into
// its own particle and every sum over particles has a fixed order, so 1 and 2 threads give
// bit-identical states (compared with memcmp, not a tolerance). The same holds for the two
// strip widths of the stencil kernels (core/lanes.hpp): every lane does the same operations.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>

#include "core/lanes.hpp"
#include "core/parallel.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/contact_fixtures.hpp"
#include "support/johnson_cook_materials.hpp"
#include "support/lattice_fixtures.hpp"

namespace gsph {
namespace {

using testing::bitIdentical;

State runWithThreads(int threads, EnergyReport* energy, const Material& material, int steps = 150,
                     double bondStretch = 0.0, FailedBondRule failedBonds = FailedBondRule::Keep,
                     double fractureEnergy = 0.0) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    SolverOptions options;
    options.bondStretch = {bondStretch};
    options.fractureEnergy = {fractureEnergy};
    options.failedBonds = {failedBonds};
    options.viscosity = {1.0, 1.0};
    options.hourglass = 0.1;
    using Kind = AxisGrading::Kind;
    const AnalyticMap map = gradedBoxMap(
        Vec3(0.2, 0.1, 0.1), {AxisGrading{Kind::OneSided, 4.0}, AxisGrading{}, AxisGrading{}});
    Simulation sim(latticeReference(map, 3, {32, 12, 12}, 7800.0, 1.2), {material}, options);
    sim.constrain(
        {"face", {0, 1, 2, 3}, [](double t, const Vec3&) { return Vec3(0, 0, 5.0 * t / 1e-5); }});
    sim.setVelocity([](const Vec3& X) { return Vec3(-40.0 * (X[0] > 0.15), 3.0 * X[1], 0.0); });
    // Large enough that the loops really run on both threads (core/parallel.hpp).
    EXPECT_GT(sim.reference().size(), kParallelThreshold);
    for (int i = 0; i < steps; ++i) sim.step();
    *energy = sim.energy();
    omp_set_num_threads(saved);
    return sim.state();
}

const Material kSteel = HypoElastic(ElasticConstants(7800.0, 200e9, 0.3));

TEST(ThreadIndependence, OneAndTwoThreadsGiveBitIdenticalStates) {
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, kSteel);
    const State s2 = runWithThreads(2, &e2, kSteel);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.v, s2.v));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.F, s2.F));
    EXPECT_EQ(std::memcmp(&s1.time, &s2.time, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&e1.kinetic, &e2.kinetic, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    // The run did something: the state moved away from rest.
    EXPECT_GT(e1.kinetic, 1.0);
}

TEST(ThreadIndependence, PlasticRunsAreBitIdenticalToo) {
    // Johnson–Cook with damage, heating and the Mie–Grüneisen pressure: the history arrays and
    // the particles' plastic work and the ledger's failure loss do not depend on the thread
    // count either.
    const Material plastic = testing::softFailingSteel();
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, plastic, 40);
    const State s2 = runWithThreads(2, &e2, plastic, 40);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.plasticStrain, s2.plasticStrain));
    EXPECT_TRUE(bitIdentical(s1.temperature, s2.temperature));
    EXPECT_TRUE(bitIdentical(s1.damage, s2.damage));
    EXPECT_TRUE(bitIdentical(s1.internalEnergy, s2.internalEnergy));
    EXPECT_TRUE(bitIdentical(s1.plasticWork, s2.plasticWork));
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_EQ(std::memcmp(&e1.elastic, &e2.elastic, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&e1.plasticWork, &e2.plasticWork, sizeof(double)), 0);
    EXPECT_GT(e1.plasticWork, 0.0);
    EXPECT_GT(e1.damageDissipation, 0.0);
}

// Nonlocal damage: the averages of the drivers over ℓ run in a fixed order per particle, so
// damage, failure and the failure loss do not depend on the thread count either.
TEST(ThreadIndependence, NonlocalDamageToo) {
    const Material plastic = testing::softFailingSteel(0.015);  // ℓ: about two spacings
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, plastic, 40);
    const State s2 = runWithThreads(2, &e2, plastic, 40);
    // Every array of the state (x, σ, D, the drivers, ...), through the field registry.
    State::forEachArrayOf(s1, s2, [](const Field& field, const auto& a, const auto& b) {
        EXPECT_TRUE(bitIdentical(a, b)) << field.name;
    });
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_GT(*std::max_element(s1.damageDriver.begin(), s1.damageDriver.end()), 1.0);
    EXPECT_GT(e1.damageDissipation, 0.0);
}

// Brittle bonds break where the -40 m/s half pulls away; the broken flags, the recomputed
// gradients and the fracture energy (failure/brittle_bonds.hpp) do not depend on the thread
// count either.
TEST(ThreadIndependence, BrokenBondsAndTheirEnergyToo) {
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, kSteel, 60, 1e-3);
    const State s2 = runWithThreads(2, &e2, kSteel, 60, 1e-3);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.bondIntact, s2.bondIntact));
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_GT(std::count(s1.bondIntact.begin(), s1.bondIntact.end(), std::uint8_t{0}), 0);
    EXPECT_NE(e1.fractureEnergy, 0.0);  // signed: bonds break here under axial compression
}

// With a fracture energy the same broken bonds soften (forces/cohesive_bonds.hpp): the
// tractions they broke under, their largest stretches, the cohesive forces and their work are
// the same bits on 1 and 2 threads.
TEST(ThreadIndependence, SofteningBondsToo) {
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, kSteel, 60, 1e-3, FailedBondRule::Keep, 2000.0);
    const State s2 = runWithThreads(2, &e2, kSteel, 60, 1e-3, FailedBondRule::Keep, 2000.0);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.v, s2.v));
    EXPECT_TRUE(bitIdentical(s1.bondIntact, s2.bondIntact));
    EXPECT_TRUE(bitIdentical(s1.cohesiveTraction, s2.cohesiveTraction));
    EXPECT_TRUE(bitIdentical(s1.cohesiveStretch, s2.cohesiveStretch));
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_GT(std::count_if(s1.cohesiveTraction.begin(), s1.cohesiveTraction.end(),
                            [](double t) { return t > 0.0; }),
              0);
    EXPECT_GT(e1.cohesiveWork, 0.0);
}

// Johnson–Cook particles that fail lose their bonds under `rule` (SolverOptions::failedBonds): the
// damage-driven breaks, the detached particles and the ledger are the same bits on 1 and 2 threads.
void expectFailedBondRunsBitIdentical(FailedBondRule rule) {
    const Material plastic = testing::softFailingSteel();
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, plastic, 60, 0.0, rule);
    const State s2 = runWithThreads(2, &e2, plastic, 60, 0.0, rule);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.v, s2.v));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.damage, s2.damage));
    EXPECT_TRUE(bitIdentical(s1.bondIntact, s2.bondIntact));
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_GT(std::count(s1.bondIntact.begin(), s1.bondIntact.end(), std::uint8_t{0}), 0);
}

// FailedBondRule::Either: a failed particle loses its bonds.
TEST(ThreadIndependence, FailedParticlesLosingTheirBondsToo) {
    expectFailedBondRunsBitIdentical(FailedBondRule::Either);
}

// The cut rule (a failed particle's cell cuts the bonds through it): the same bits too.
TEST(ThreadIndependence, FailedParticlesCuttingTheBondsAcrossThemToo) {
    expectFailedBondRunsBitIdentical(FailedBondRule::Cut);
}

// Contact between two bodies (the current-configuration search, the pair forces and energy),
// a wall with friction, gravity and a set force: still bit-identical.
TEST(ThreadIndependence, ContactRunsAreBitIdenticalToo) {
    const auto run = [](int threads, EnergyReport* energy) {
        const int saved = omp_get_max_threads();
        omp_set_num_threads(threads);
        using testing::Box;
        SolverOptions options;
        options.viscosity = {1.0, 1.0};
        options.hourglass = 0.1;
        Simulation sim(
            testing::boxBodies(
                {Box{Vec3::Zero(), Vec3(0.016, 0.016, 0.010), {16, 16, 10}},
                 Box{Vec3(0.002, 0.003, 0.010), Vec3(0.012, 0.012, 0.012), {12, 12, 12}}}),
            {kSteel, kSteel}, options);
        EXPECT_GT(sim.reference().size(), kParallelThreshold);
        sim.addWall({"floor", Vec3::Zero(), Vec3(-0.02, 0.0, 1.0), Vec3(0.5, 0.0, 0.0), 0.3});
        sim.setGravity(Vec3(0.0, 0.0, -9.81));
        sim.applyForce({"corner", {0, 1, 2}, Vec3(50.0, 0.0, 0.0)});
        const Reference& ref = sim.reference();
        std::vector<Vec3> v(static_cast<std::size_t>(ref.size()), Vec3::Zero());
        for (std::size_t a = 0; a < v.size(); ++a)
            if (ref.body[a] == 1) v[a] = Vec3(3.0, 0.0, -60.0);
        sim.setVelocities(v);
        for (int i = 0; i < 40; ++i) sim.step();
        EXPECT_GT(sim.integrator().stage<PairContactStage>()->contact().pairsInContact(), 0);
        *energy = sim.energy();
        omp_set_num_threads(saved);
        return sim.state();
    };
    EnergyReport e1, e2;
    const State s1 = run(1, &e1);
    const State s2 = run(2, &e2);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.v, s2.v));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.contactForce, s2.contactForce));
    EXPECT_EQ(s1.contactForce.size(), 4u);
    EXPECT_EQ(std::memcmp(&s1.time, &s2.time, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_GT(e1.contactEnergy, 0.0);
    EXPECT_NE(e1.externalWork, 0.0);
}

// Each strip width against the portable 2-lane strips; a width this processor lacks is
// reported as skipped, not passed.
class StripWidth : public ::testing::TestWithParam<int> {};

bool hasLanes(int width) {
    limitLanes(width);
    const bool available = laneWidth() >= width;
    limitLanes(8);
    return available;
}

TEST_P(StripWidth, GivesBitIdenticalStates) {
    const int width = GetParam();
    if (!hasLanes(width)) GTEST_SKIP() << "this processor has no " << width << "-lane strips";
    limitLanes(2);
    EnergyReport ep;
    const State portable = runWithThreads(1, &ep, kSteel);
    EXPECT_GT(ep.kinetic, 1.0);
    limitLanes(width);
    EnergyReport ew;
    const State wide = runWithThreads(1, &ew, kSteel);
    limitLanes(8);
    EXPECT_TRUE(bitIdentical(wide.x, portable.x)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.v, portable.v)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.cauchy, portable.cauchy)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.F, portable.F)) << width << " lanes";
    EXPECT_EQ(std::memcmp(&wide.ledger, &portable.ledger, sizeof(EnergyLedger)), 0);
}

// Johnson–Cook with damage, heating and the Mie–Grüneisen pressure: F, L and the force factors
// run in strips, the return mapping one particle at a time between them.
TEST_P(StripWidth, GivesBitIdenticalPlasticStates) {
    const int width = GetParam();
    if (!hasLanes(width)) GTEST_SKIP() << "this processor has no " << width << "-lane strips";
    const Material plastic = testing::softFailingSteel();
    limitLanes(2);
    EnergyReport ep;
    const State portable = runWithThreads(1, &ep, plastic, 40);
    limitLanes(width);
    EnergyReport ew;
    const State wide = runWithThreads(1, &ew, plastic, 40);
    limitLanes(8);
    EXPECT_GT(ep.plasticWork, 0.0);
    EXPECT_TRUE(bitIdentical(wide.x, portable.x)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.v, portable.v)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.cauchy, portable.cauchy)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.F, portable.F)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.plasticStrain, portable.plasticStrain)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.plasticWork, portable.plasticWork)) << width << " lanes";
    EXPECT_TRUE(bitIdentical(wide.damage, portable.damage)) << width << " lanes";
    EXPECT_EQ(std::memcmp(&wide.ledger, &portable.ledger, sizeof(EnergyLedger)), 0);
}

INSTANTIATE_TEST_SUITE_P(ThreadIndependence, StripWidth, ::testing::Values(4, 8),
                         [](const ::testing::TestParamInfo<int>& param) {
                             return std::to_string(param.param) + "Lanes";
                         });

}  // namespace
}  // namespace gsph
