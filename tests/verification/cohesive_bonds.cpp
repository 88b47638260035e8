// SPDX-License-Identifier: MIT
// Softening bonds (forces/cohesive_bonds.hpp): the cohesive law's calibration from the fracture
// energy, and the energy a crack takes in a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "forces/cohesive_bonds.hpp"
#include "integrator/energy.hpp"
#include "simulation.hpp"
#include "support/lattice_fixtures.hpp"
#include "support/pulled_bar.hpp"

namespace gsph {
namespace {

// Sums term(a, k) over the bonds whose reference segment crosses the plane x = x0, each once,
// if keep(the end below the plane) says so.
template <class Keep, class Term>
double sumAcross(const Reference& ref, double x0, Keep keep, Term term) {
    double sum = 0.0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto b =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            const double xa = ref.X[static_cast<std::size_t>(a)][0];
            if (xa < x0 && ref.X[b][0] > x0 && keep(a)) sum += term(a, k);
        }
    return sum;
}

// A plane crack through a cubic (square, in plane strain) lattice normal to an axis: the bonds
// it cuts hold the fracture energy. The calibration averages over the plane's orientations; on
// the lattice an axis plane gets exactly (Δx = 1, sums over the support's offsets ξ)
//   3-D: 4 Σ_{ξx>0} ξ_x |ξ| / Σ_all |ξ|²   (κ = 0.9, 26 neighbours: 4 (1 + 4√2 + 4√3) / 54 =
//        1.0063; κ = 1.2: 4 (1 + 4√2 + 4√3 + 4√5 + 2 (2 + 4√5)) / 198 = 0.8973, its support
//        holding the offsets (2, 1, 0) but not (2, 1, 1));
//   2-D: π Σ_{ξx>0} ξ_x |ξ| / Σ_all |ξ|²   (κ = 0.9: π (1 + 2√2) / 12 = 1.0022; κ = 1.2:
//        π (1 + 2√2 + 2√5 + 4 + 4√5) / 68 = 0.9815).
// Counted over the bonds whose lower end lies in the central columns of a 12-cell block, far
// enough from its faces (5 cells) that both ends of every such bond have whole neighbourhoods.
TEST(CohesiveBonds, AnAxisPlaneCrackOfALatticeTakesItsShareOfTheFractureEnergy) {
    const double g0 = 1000.0, dx = 1e-3;  // [J/m²], [m]
    const int cells = 12;
    const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r5 = std::sqrt(5.0);
    for (const int dim : {3, 2})
        for (const double kappa : {0.9, 1.2}) {
            const bool planar = dim == 2;
            const Reference ref = testing::builtReference(
                gradedBoxMap(Vec3(cells * dx, cells * dx, planar ? 0.0 : cells * dx), {}), dim,
                {cells, cells, planar ? 1 : cells}, kappa, 7800.0);
            const auto n = static_cast<std::size_t>(ref.size());
            const BrittleBonds bonds(ref, std::vector<double>(n, 1e-3));
            CohesiveBondStage stage(ref, bonds, std::vector<double>(n, 1e-3),
                                    std::vector<double>(n, g0));
            const auto column = [&](double x) { return static_cast<int>(std::floor(x / dx)); };
            const auto central = [&](Index a) {
                const Vec3& X = ref.X[static_cast<std::size_t>(a)];
                return column(X[1]) >= 5 && column(X[1]) <= 6 &&
                       (planar || (column(X[2]) >= 5 && column(X[2]) <= 6));
            };
            const double energy = sumAcross(ref, 6.0 * dx, central, [&](Index a, Index k) {
                return stage.separationEnergy(a, k);
            });
            const double expected =
                planar
                    ? (kappa < 1.0
                           ? std::numbers::pi * (1.0 + 2.0 * r2) / 12.0
                           : std::numbers::pi * (1.0 + 2.0 * r2 + 2.0 * r5 + 4.0 + 4.0 * r5) / 68.0)
                    : (kappa < 1.0
                           ? 4.0 * (1.0 + 4.0 * r2 + 4.0 * r3) / 54.0
                           : 4.0 * (1.0 + 4.0 * r2 + 4.0 * r3 + 4.0 * r5 + 2.0 * (2.0 + 4.0 * r5)) /
                                 198.0);
            const double area = planar ? 2.0 * dx : 4.0 * dx * dx;  // per m of thickness in 2-D
            const double perArea = energy / (g0 * area);
            std::printf(
                "[cohesive] %d-D, κ = %.1f: an axis plane crack holds %.6f G0 (lattice: %.6f)\n",
                dim, kappa, perArea, expected);
            EXPECT_NEAR(perArea, expected, 1e-12);
        }
}

// The halves of a bar (ν = 0, 40 × 4 × 4 cells of 1 mm) whose mid-plane bonds broke at the onset
// s0 under the normal stress t0, flying apart at ±v0: the cohesive bonds hold them, stretch,
// soften and let go once each has taken its w_ab. Then the ledger's cohesive work is the sum
// of w_ab over the cut bonds (to the trapezoid rule's error), the energy total holds, the
// momentum stays zero, no other bond breaks, and the bar's section carries G0 per unit area
// within what its free faces add (their particles' smaller neighbourhoods are calibrated up).
TEST(CohesiveBonds, TheHalvesOfABarSeparateOnceTheCutBondsHaveTakenTheirEnergy) {
    const ElasticConstants steel(7800.0, 200e9, 0.0);
    const double s0 = 2e-3, t0 = 1e8, g0 = 1000.0, v0 = 5.0, length = 0.04, mid = 0.02;
    SolverOptions options;
    options.bondStretch = {s0};
    options.fractureEnergy = {g0};
    Simulation sim(latticeReference(gradedBoxMap(Vec3(length, 0.004, 0.004), {}), 3, {40, 4, 4},
                                    steel.density, 0.9),
                   {HypoElastic(steel)}, options);
    const Reference& ref = sim.reference();
    const auto pairs = static_cast<std::size_t>(ref.pairs.pairs());
    State state = State::atRest(ref.X, pairs);
    state.cohesiveTraction.assign(pairs, 0.0);
    state.cohesiveStretch.assign(pairs, 0.0);
    Index cut = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        state.v[ia] = Vec3(ref.X[ia][0] < mid ? -v0 : v0, 0.0, 0.0);
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto ik = static_cast<std::size_t>(k);
            const auto b = static_cast<std::size_t>(ref.pairs.neighbor[ik]);
            if ((ref.X[ia][0] - mid) * (ref.X[b][0] - mid) >= 0.0) continue;
            state.bondIntact[ik] = 0;
            state.cohesiveTraction[ik] = t0;
            state.cohesiveStretch[ik] = s0;
            if (b > ia) ++cut;
        }
    }
    state.dt = 0.2 * 1e-3 / steel.pWaveSpeed();
    sim.resume(state, "the cut bar");
    const CohesiveBondStage* stage = sim.integrator().stage<CohesiveBondStage>();
    ASSERT_NE(stage, nullptr);
    const double separation = sumAcross(
        ref, mid, [](Index) { return true; },
        [&](Index a, Index k) { return stage->separationEnergy(a, k); });
    // Set at rest with their largest stretch at s0, the cut bonds first reload along the secant
    // to (s0, f0), taking ½ f0 s0 |ξ| more each (a bond broken in a run starts where it broke).
    const double reload = sumAcross(
        ref, mid, [](Index) { return true; },
        [&](Index a, Index k) {
            const auto b =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            return 0.5 * stage->law(a, k, t0).peak * s0 *
                   (ref.X[b] - ref.X[static_cast<std::size_t>(a)]).norm();
        });
    const double kinetic0 = measureEnergy(ref, sim.state(), sim.bodies()).kinetic;
    const double total0 = measureEnergy(ref, sim.state(), sim.bodies()).total();
    double worstImbalance = 0.0, worstMomentum = 0.0;
    // Each bond opens by Δs |ξ| ≈ 4.5 µm at about 2 v0: 4 µs is ample once the halves' inner
    // layers have decelerated; the bar's wave crosses a half in 4 µs.
    sim.advanceTo(2e-5, [&](const State& s) {
        const EnergyReport e = measureEnergy(ref, s, sim.bodies());
        worstImbalance = std::max(worstImbalance, std::abs(e.total() - total0));
        worstMomentum = std::max(worstMomentum, e.momentum.norm());
    });
    const State& end = sim.state();
    // Every cut bond has let go: the cohesive forces are zero.
    double largestCohesive = 0.0;
    for (const Vec3& f : sim.integrator().channels().parts.cohesive)
        largestCohesive = std::max(largestCohesive, f.norm());
    const EnergyReport e = measureEnergy(ref, end, sim.bodies());
    const double area = 0.004 * 0.004;
    double leftVelocity = 0.0, leftMass = 0.0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        if (ref.X[ia][0] >= mid) continue;
        leftVelocity += ref.mass[ia] * end.v[ia][0];
        leftMass += ref.mass[ia];
    }
    leftVelocity /= leftMass;
    std::printf(
        "[cohesive] cut bar: %d bonds cut, Σ w_ab %.6e J (%.4f G0 A), reloading %.4e J; cohesive "
        "work %.6e J (%+.2e of the sum); kinetic %.4e → %.4e J, elastic %.3e J; worst |Δtotal| "
        "%.2e of the "
        "kinetic energy; |momentum| ≤ %.1e kg m/s; left half at %.4f m/s; %ld steps; largest "
        "cohesive force left %.1e N\n",
        cut, separation, separation / (g0 * area), reload, e.cohesiveWork,
        e.cohesiveWork / (separation + reload) - 1.0, kinetic0, e.kinetic, e.elastic,
        worstImbalance / kinetic0, worstMomentum, leftVelocity, end.step, largestCohesive);
    EXPECT_EQ(sim.integrator().bonds().brokenPairs(), cut);  // no other bond broke
    EXPECT_NEAR(e.cohesiveWork / (separation + reload), 1.0, 1e-4);
    EXPECT_NEAR(separation / (g0 * area), 1.0, 0.06);  // the free faces add 5.7 %
    EXPECT_LT(worstImbalance, 5e-4 * kinetic0);
    EXPECT_LT(worstMomentum, 1e-12 * leftMass * v0);
    EXPECT_LT(leftVelocity, 0.0);  // the halves fly apart
    EXPECT_EQ(largestCohesive, 0.0);
}

// The pulled bar (support/pulled_bar.hpp, ±5 m/s) with a fracture energy: its bonds
// break where the stretch reaches εmax (the driven layers first, then all along: measured 2920
// pairs, 80 % of them under a tensile normal stress, so softening) and soften there
// (State::cohesiveTraction records the normal stress each broke under, the same on both sides of
// a pair), the ends do work, and the ledger's total (kinetic + elastic + fracture + cohesive −
// boundary work) holds: measured 3.0e-3 of the work.
TEST(CohesiveBonds, ABarPulledApartSoftensTheBondsItBreaksWithTheLedgerClosed) {
    const double g0 = 2000.0;
    SolverOptions options;
    options.bondStretch = {2e-3};
    options.fractureEnergy = {g0};
    const auto bar = testing::pulledBar(options, 5.0);
    Simulation& sim = *bar;
    const Reference& ref = sim.reference();
    sim.start();
    const double total0 = sim.energy().total();
    double worstImbalance = 0.0;
    sim.advanceTo(2e-5, [&](const State&) {
        worstImbalance = std::max(worstImbalance, std::abs(sim.energy().total() - total0));
    });
    const State& s = sim.state();
    const EnergyReport e = sim.energy();
    Index softening = 0, asymmetric = 0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto ik = static_cast<std::size_t>(k);
            if (s.cohesiveTraction[ik] <= 0.0) continue;
            ++softening;
            const Index b = ref.pairs.neighbor[ik];
            for (Index m = ref.pairs.begin(b); m < ref.pairs.end(b); ++m)
                if (ref.pairs.neighbor[static_cast<std::size_t>(m)] == a &&
                    (s.cohesiveTraction[static_cast<std::size_t>(m)] != s.cohesiveTraction[ik] ||
                     s.cohesiveStretch[static_cast<std::size_t>(m)] != s.cohesiveStretch[ik]))
                    ++asymmetric;
        }
    const double area = 0.004 * 0.004;
    std::printf(
        "[cohesive] pulled bar: %d pairs broken, %d softening entries; boundary work %.4e J, "
        "kinetic %.4e, elastic %.4e, fracture %.4e, cohesive %.4e J (%.3f G0 A); worst |Δtotal| "
        "%.2e of the work; %ld steps\n",
        sim.integrator().bonds().brokenPairs(), softening, e.boundaryWork, e.kinetic, e.elastic,
        e.fractureEnergy, e.cohesiveWork, e.cohesiveWork / (g0 * area),
        worstImbalance / e.boundaryWork, s.step);
    EXPECT_GT(softening, 0);
    // Bonds that broke where the normal stress across them was not tensile break sharply.
    EXPECT_LE(softening, 2 * sim.integrator().bonds().brokenPairs());
    EXPECT_EQ(asymmetric, 0);
    EXPECT_GT(e.cohesiveWork, 0.0);
    EXPECT_LT(worstImbalance, 5e-3 * e.boundaryWork);
}

}  // namespace
}  // namespace gsph
