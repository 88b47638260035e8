// SPDX-License-Identifier: MIT
// Results do not depend on the thread count (issue #2, DESIGN §9): every loop gathers into
// its own particle and every sum over particles has a fixed order, so 1 and 2 threads give
// bit-identical states (compared with memcmp, not a tolerance). The same holds for the two
// strip widths of the stencil kernels (core/lanes.hpp): every lane does the same operations.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

#include "core/lanes.hpp"
#include "core/parallel.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

State runWithThreads(int threads, EnergyReport* energy, const Material& material, int steps = 150) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    SolverOptions options;
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

template <class T>
bool bitIdentical(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
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
    // the ledger's plastic work and failure loss do not depend on the thread count either.
    JohnsonCookParams p;
    p.yieldStress = 2e6;  // low, so that the 40 m/s impact flows plastically at once
    p.hardeningModulus = 50e6;
    p.hardeningExponent = 0.3;
    p.strainRateCoefficient = 0.02;
    p.meltingTemperature = 1800.0;
    p.specificHeat = 450.0;
    const ElasticConstants e(7800.0, 200e9, 0.3);
    const Material plastic =
        JohnsonCook(e, p, EquationOfState::mieGruneisen(7800.0, {4570.0, 1.49, 1.93}),
                    JohnsonCookDamage{{0.0, 0.001, 0.0, 0.0, 0.0}});
    EnergyReport e1, e2;
    const State s1 = runWithThreads(1, &e1, plastic, 40);
    const State s2 = runWithThreads(2, &e2, plastic, 40);
    EXPECT_TRUE(bitIdentical(s1.x, s2.x));
    EXPECT_TRUE(bitIdentical(s1.cauchy, s2.cauchy));
    EXPECT_TRUE(bitIdentical(s1.plasticStrain, s2.plasticStrain));
    EXPECT_TRUE(bitIdentical(s1.temperature, s2.temperature));
    EXPECT_TRUE(bitIdentical(s1.damage, s2.damage));
    EXPECT_TRUE(bitIdentical(s1.internalEnergy, s2.internalEnergy));
    EXPECT_EQ(std::memcmp(&s1.ledger, &s2.ledger, sizeof(EnergyLedger)), 0);
    EXPECT_EQ(std::memcmp(&e1.elastic, &e2.elastic, sizeof(double)), 0);
    EXPECT_GT(e1.plasticWork, 0.0);
    EXPECT_GT(e1.damageDissipation, 0.0);
}

TEST(ThreadIndependence, EveryStripWidthGivesBitIdenticalStates) {
    limitLanes(2);
    EnergyReport ep;
    const State portable = runWithThreads(1, &ep, kSteel);
    EXPECT_GT(ep.kinetic, 1.0);
    for (const int width : {4, 8}) {
        limitLanes(width);
        if (laneWidth() < width) continue;  // the processor has no such width
        EnergyReport ew;
        const State wide = runWithThreads(1, &ew, kSteel);
        EXPECT_TRUE(bitIdentical(wide.x, portable.x)) << width << " lanes";
        EXPECT_TRUE(bitIdentical(wide.v, portable.v)) << width << " lanes";
        EXPECT_TRUE(bitIdentical(wide.cauchy, portable.cauchy)) << width << " lanes";
        EXPECT_TRUE(bitIdentical(wide.F, portable.F)) << width << " lanes";
        EXPECT_EQ(std::memcmp(&wide.ledger, &portable.ledger, sizeof(EnergyLedger)), 0);
    }
    limitLanes(8);
}

}  // namespace
}  // namespace gsph
