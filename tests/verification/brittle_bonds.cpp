// SPDX-License-Identifier: MIT
// Brittle bonds (DESIGN §5): a bond breaks for good at the stretch εmax, and the
// kinematics stay consistent after it does (DESIGN §3).
//
// The bar test: a free 3-D bar (ν = 0, so the bar wave is exactly 1-D at c = √(E/ρ)) carries two
// smooth tension pulses, one from each end towards the middle: right-running
// v_x = −v0 s(ξ), σ_xx = −ρc v_x and its mirror image, s(ξ) = ½(1 − cos 2πξ) over a length λ.
// Each pulse stretches the bar by at most v0/c; where they meet, the stretch doubles. With
// εmax = 1.5 v0/c no bond can break before they meet, and the middle reaches εmax when the two
// pulses' leading flanks each give 0.75 v0/c there: s(ξ) = 0.75 on the leading flank, ξ = 2/3,
// at t* = (L/2 − x0 − 2λ/3)/c (x0: where a pulse starts). The criterion says: the first bonds
// break at t*, at the middle; the bar comes apart; and no bond breaks outside the
// stretch of bar where the pulses overlap in tension (|X − L/2| < λ/2), since elsewhere the
// stretch never exceeds v0/c. (Within that stretch the sum of the two flanks is near εmax over
// many spacings, and the release wave of the first crack fragments it, as it would a real
// brittle bar: measured, breaks within ±25 spacings. Pulling the ends instead makes the driven
// layer the most stretched place: a kinked drive is noisier there than the factor 2 allows.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/error.hpp"
#include "failure/brittle_bonds.hpp"
#include "io/snapshot.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "simulation.hpp"
#include "support/ductile_bar.hpp"
#include "support/johnson_cook_materials.hpp"
#include "support/lattice_fixtures.hpp"
#include "support/pulled_bar.hpp"

namespace gsph {
namespace {

// The pieces a body is in: union–find over its intact bonds, the root of each particle's piece.
std::vector<Index> bondPieces(const Reference& ref, const std::vector<std::uint8_t>& intact) {
    std::vector<Index> root(static_cast<std::size_t>(ref.size()));
    for (Index a = 0; a < ref.size(); ++a) root[static_cast<std::size_t>(a)] = a;
    const auto find = [&](Index a) {
        while (root[static_cast<std::size_t>(a)] != a)
            a = root[static_cast<std::size_t>(a)] =
                root[static_cast<std::size_t>(root[static_cast<std::size_t>(a)])];
        return a;
    };
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k)
            if (intact[static_cast<std::size_t>(k)] != 0)
                root[static_cast<std::size_t>(find(a))] =
                    find(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
    for (Index a = 0; a < ref.size(); ++a) root[static_cast<std::size_t>(a)] = find(a);
    return root;
}

TEST(BrittleBonds, AffineMotionGivesExactFAfterBondsBreak) {
    // A block cut by a plane: every bond across x = 0.5 broken. Over the surviving bonds the
    // metric is recomputed, so F = I at rest and F = A under x = A X, on both faces of the cut.
    const Reference ref =
        testing::builtReference(gradedBoxMap(Vec3(1.0, 0.6, 0.4), {}), 3, {10, 6, 4});
    State state = State::atRest(ref.X, static_cast<std::size_t>(ref.pairs.pairs()));
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto b =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            if ((ref.X[static_cast<std::size_t>(a)][0] - 0.5) * (ref.X[b][0] - 0.5) < 0.0)
                state.bondIntact[static_cast<std::size_t>(k)] = 0;
        }
    BrittleBonds bonds(ref, std::vector<double>(static_cast<std::size_t>(ref.size()), 0.01));
    bonds.attach(state);
    EXPECT_EQ(bonds.brokenPairs(),
              static_cast<Index>(brokenBonds(ref.pairs, state.bondIntact).size()));
    Mat3 A;
    A << 1.1, 0.2, -0.05, 0.03, 0.95, 0.1, -0.02, 0.07, 1.2;
    std::vector<Vec3> x(ref.X.size());
    for (std::size_t a = 0; a < x.size(); ++a) x[a] = A * ref.X[a] + Vec3(0.3, -0.1, 2.0);
    double worstRest = 0.0, worstAffine = 0.0;
    Index damaged = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        ASSERT_FALSE(bonds.detached(a)) << "particle " << a;
        if (!bonds.view(state).allIntact(a, a + 1)) ++damaged;
        const Mat3& G = bonds.G()[static_cast<std::size_t>(a)];
        Mat3 gx, gv;
        thetaGradients(ref, a, ref.X.data(), ref.X.data(), gx, gv, state.bondIntact.data());
        worstRest =
            std::max(worstRest, (gx * G.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff());
        thetaGradients(ref, a, x.data(), x.data(), gx, gv, state.bondIntact.data());
        worstAffine = std::max(worstAffine, (gx * G.transpose() - A).cwiseAbs().maxCoeff());
    }
    std::printf("[bonds] cut block: %d damaged particles, F = I to %.1e, F = A to %.1e\n", damaged,
                worstRest, worstAffine);
    EXPECT_EQ(damaged, 4 * 6 * 4);  // two layers of 6×4 on each side (κ = 1.2: support 2.4)
    EXPECT_LT(worstRest, 1e-10);
    EXPECT_LT(worstAffine, 1e-10);
}

TEST(BrittleBonds, BarBreaksWhereAndWhenTheStretchCriterionSays) {
    const ElasticConstants steel(7800.0, 200e9, 0.0);
    const double c = steel.barWaveSpeed(), v0 = 1.0, length = 0.6, lambda = 0.12, x0 = 0.01;
    const double epsMax = 1.5 * v0 / c;
    SolverOptions options;
    options.bondStretch = {epsMax};
    options.hourglass = 0.05;
    Simulation sim(latticeReference(gradedBoxMap(Vec3(length, 0.008, 0.008), {}), 3, {300, 4, 4},
                                    steel.density, 1.2),
                   {HypoElastic(steel)}, options);
    const Reference& ref = sim.reference();
    const double twoPi = 2.0 * std::acos(-1.0);
    const auto pulse = [&](double X) {  // tension pulses: from the left end and its mirror image
        const double xi = (X < 0.5 * length ? X : length - X) - x0;
        return xi > 0.0 && xi < lambda ? 0.5 * (1.0 - std::cos(twoPi * xi / lambda)) : 0.0;
    };
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const double X = ref.X[ia][0], side = X < 0.5 * length ? -1.0 : 1.0;
        sim.state().v[ia] = Vec3(side * v0 * pulse(X), 0.0, 0.0);
        sim.state().cauchy[ia](0, 0) = steel.density * c * v0 * pulse(X);
    }
    const double expected = (0.5 * length - x0 - 2.0 * lambda / 3.0) / c;
    double firstBreak = -1.0;
    std::vector<std::array<Index, 2>> firstBroken;
    sim.advanceTo(1.5 * expected, [&](const State& s) {
        if (firstBreak < 0.0 && sim.integrator().bonds().brokenPairs() > 0) {
            firstBreak = s.time;
            firstBroken = brokenBonds(ref.pairs, s.bondIntact);
        }
    });
    ASSERT_GT(firstBreak, 0.0) << "no bond broke";
    std::printf(
        "[bonds] bar: first break at %.3f µs, criterion %.3f µs (%+.2f %%), %d pairs "
        "broken\n",
        1e6 * firstBreak, 1e6 * expected, 100 * (firstBreak / expected - 1),
        sim.integrator().bonds().brokenPairs());
    EXPECT_NEAR(firstBreak / expected, 1.0, 0.03);

    // Where: the first bonds to break lie at the middle (bond centre within 1.5 spacings);
    // at the end the two ends of the bar are apart (no path of intact bonds joins them), and
    // no bond has broken outside the overlap of the pulses.
    const double middle = 0.5 * length, spacing = length / 300;
    const auto centre = [&](Index a, Index b) {
        return 0.5 *
               (ref.X[static_cast<std::size_t>(a)][0] + ref.X[static_cast<std::size_t>(b)][0]);
    };
    for (const auto& [a, b] : firstBroken)
        EXPECT_LT(std::abs(centre(a, b) - middle), 1.5 * spacing) << "bond " << a << "–" << b;
    const State& s = sim.state();
    double farthest = 0.0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k)
            if (s.bondIntact[static_cast<std::size_t>(k)] == 0)
                farthest = std::max(
                    farthest,
                    std::abs(centre(a, ref.pairs.neighbor[static_cast<std::size_t>(k)]) - middle));
    const std::vector<Index> piece = bondPieces(ref, s.bondIntact);
    EXPECT_NE(piece.front(), piece.back()) << "the two ends are still joined";
    std::printf(
        "[bonds] bar: %zu bonds broke first, at the middle; the ends came apart; broken "
        "bonds reach %.1f spacings from the middle (bound %.1f)\n",
        firstBroken.size(), farthest / spacing, 0.5 * lambda / spacing);
    EXPECT_LT(farthest, 0.5 * lambda);
}

// Energy balance of a bar pulled apart: both end layers are driven outwards at v0, so
// the bar is stretched until bonds break and it comes apart, while the prescribed velocities do
// work on it. The ledger's total (kinetic + elastic + fracture − boundary work; no viscosity or
// hourglass control here) must stay at its value after the start (the driven layers' ½mv0²,
// given at t = 0 by the prescription) through the breaking, within 1 % of the work done.
// Measured: 0.48 % with the fracture term, which itself is 6.2 % of the work (without it the
// total drifts by that much); with εmax out of reach nothing breaks, the fracture term is
// exactly 0 and the total holds to 0.14 %.
struct PulledBar {
    Index broken = 0;
    Index detached = 0;
    EnergyReport energy;
    double worstImbalance = 0.0;  ///< max over the steps of |total| [J]
};

PulledBar pullBarApart(double epsMax) {
    const double v0 = 5.0, length = testing::kPulledBarLength;
    SolverOptions options;
    options.bondStretch = {epsMax};
    const auto bar = testing::pulledBar(options, v0);
    Simulation& sim = *bar;
    const Reference& ref = sim.reference();
    PulledBar out;
    // Time for the ends to stretch the bar by about 1 % (the bonds break well before that).
    const double endTime = 0.01 * length / (2.0 * v0);
    sim.start();
    const double initialTotal = sim.energy().total();  // the driven layers' ½mv0² at t = 0
    sim.advanceTo(endTime, [&](const State&) {
        out.worstImbalance =
            std::max(out.worstImbalance, std::abs(sim.energy().total() - initialTotal));
    });
    out.energy = sim.energy();
    out.broken = sim.integrator().bonds().brokenPairs();
    for (Index a = 0; a < ref.size(); ++a)
        if (sim.integrator().bonds().detached(a)) ++out.detached;
    return out;
}

TEST(BrittleBonds, EnergyBalanceOfABarPulledApartBooksTheFractureEnergy) {
    const PulledBar broken = pullBarApart(2e-3);
    const PulledBar intact = pullBarApart(1.0);
    const EnergyReport& e = broken.energy;
    std::printf(
        "[bonds] pulled bar: %d pairs broken, %d particles detached; boundary work %.4e J, "
        "kinetic %.4e, elastic %.4e, viscous %.3e, hourglass %.3e, fracture %.4e J; worst "
        "|total| %.3e J (%.2e of the work); intact: worst |total| %.3e J (%.2e)\n",
        broken.broken, broken.detached, e.boundaryWork, e.kinetic, e.elastic, e.viscousWork,
        e.hourglassWork, e.fractureEnergy, broken.worstImbalance,
        broken.worstImbalance / e.boundaryWork, intact.worstImbalance,
        intact.worstImbalance / intact.energy.boundaryWork);
    ASSERT_GT(broken.broken, 0);
    EXPECT_GT(e.boundaryWork, 0.0);
    EXPECT_LT(broken.worstImbalance, 1e-2 * e.boundaryWork);
    EXPECT_GT(e.fractureEnergy, 3e-2 * e.boundaryWork);  // the term matters at this tolerance
    EXPECT_EQ(intact.broken, 0);
    EXPECT_EQ(intact.energy.fractureEnergy, 0.0);
    EXPECT_LT(intact.worstImbalance, 1e-2 * intact.energy.boundaryWork);
}

// Initial cracks: the bonds whose reference segment crosses a planar patch start
// broken. Brute force: a pair crosses the patch when its segment X_a + t (X_b − X_a) meets the
// patch's plane at t ∈ [0, 1] inside the parallelogram, solved here as one 3×3 system
// [edge1 edge2 −(X_b − X_a)] (s, u, t) = X_a − corner (planes placed off every particle, so no
// end lies on one). A partial patch (half the section, tilted) and a full one on a graded block.
TEST(BrittleBonds, PrecrackBreaksExactlyTheBondsCrossingItsPatch) {
    const Reference ref = testing::builtReference(
        gradedBoxMap(Vec3(1.0, 0.6, 0.4),
                     {AxisGrading{AxisGrading::Kind::OneSided, 1.5}, AxisGrading{}, AxisGrading{}}),
        3, {12, 8, 5});
    const std::vector<CrackPatch> patches = {
        // Tilted, across z, from y = −0.1 to y = 0.33: a notch ending inside the block.
        {Vec3(0.4713, -0.1, -0.05), Vec3(0.0517, 0.43, 0.0), Vec3(0.0, 0.0, 0.5)},
        // A second, normal to z, over part of x and y.
        {Vec3(0.6, 0.05, 0.2117), Vec3(0.3, 0.0, 0.0), Vec3(0.0, 0.35, 0.0)},
    };
    const auto crosses = [&](const Vec3& Xa, const Vec3& Xb) {
        for (const CrackPatch& p : patches) {
            Mat3 A;
            A << p.edge1, p.edge2, -(Xb - Xa);
            // A segment parallel to the plane never crosses it.
            if (std::abs(A.determinant()) <=
                1e-12 * p.edge1.norm() * p.edge2.norm() * (Xb - Xa).norm())
                continue;
            const Vec3 sut = A.fullPivLu().solve(Xa - p.corner);
            if (sut.minCoeff() >= 0.0 && sut.maxCoeff() <= 1.0) return true;
        }
        return false;
    };
    Index expected = 0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            if (b > a &&
                crosses(ref.X[static_cast<std::size_t>(a)], ref.X[static_cast<std::size_t>(b)]))
                ++expected;
        }
    std::vector<std::uint8_t> intact(static_cast<std::size_t>(ref.pairs.pairs()), 1);
    const Index broken = breakBondsAcross(ref, patches, intact);
    // Both directions of every pair agree, and the flags are exactly the brute force's.
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            const bool cut =
                crosses(ref.X[static_cast<std::size_t>(a)], ref.X[static_cast<std::size_t>(b)]);
            ASSERT_EQ(intact[static_cast<std::size_t>(k)] == 0, cut) << "pair " << a << "–" << b;
        }
    std::printf("[bonds] precrack: %d pairs cut, brute force %d\n", broken, expected);
    EXPECT_GT(expected, 100);
    EXPECT_EQ(broken, expected);
    EXPECT_EQ(static_cast<std::size_t>(broken), brokenBonds(ref.pairs, intact).size());
    // Applying the patches again breaks nothing new.
    EXPECT_EQ(breakBondsAcross(ref, patches, intact), 0);
    EXPECT_THROW(
        breakBondsAcross(ref, {{Vec3::Zero(), Vec3::UnitX(), 2.0 * Vec3::UnitX()}}, intact),
        InputError);
}

// A notch whose tip lies on a cell face: mirror-image bonds cross its plane exactly on the tip
// edge. They are cut (edges included), and positions perturbed by round-off (1e-12 of the
// spacing, as two converters of the same layout give) cut the same bonds.
TEST(BrittleBonds, PrecrackEdgeOnACellFaceCutsTheSameBondsDespiteRoundOff) {
    Reference ref = testing::builtReference(gradedBoxMap(Vec3(1.0, 0.8, 0.4), {}), 3, {10, 8, 4});
    const std::vector<CrackPatch> notch = {
        {Vec3(-0.05, 0.4, -0.05), Vec3(0.0, 0.0, 0.5), Vec3(0.55, 0.0, 0.0)}};  // tip x = 0.5
    const std::vector<CrackPatch> shorter = {
        {Vec3(-0.05, 0.4, -0.05), Vec3(0.0, 0.0, 0.5), Vec3(0.54, 0.0, 0.0)}};  // tip x = 0.49
    const auto cut = [&](const std::vector<CrackPatch>& patches) {
        std::vector<std::uint8_t> intact(static_cast<std::size_t>(ref.pairs.pairs()), 1);
        return breakBondsAcross(ref, patches, intact);
    };
    const Index exact = cut(notch);
    EXPECT_GT(exact, cut(shorter));  // the bonds crossing at x = 0.5 itself are cut
    for (std::size_t a = 0; a < ref.X.size(); ++a)
        ref.X[a] += 1e-13 * Vec3(std::sin(3.0 * static_cast<double>(a)),
                                 std::cos(5.0 * static_cast<double>(a)), 0.0);
    std::printf("[bonds] notch tip on a cell face: %d pairs cut, %d after round-off\n", exact,
                cut(notch));
    EXPECT_EQ(cut(notch), exact);
}

// A graded block cut through by a precrack at x = 0.5 (unbreakable bonds: εmax = 0), its two
// halves given opposite velocities ±v0 along x. At t = 0, F = I on both faces of the cut; then
// the halves fly apart as rigid bodies: no force acts across the patch, so every velocity stays
// ±v0 and every stress zero, and no particle is detached.
TEST(BrittleBonds, PrecrackedBlockPulledApartCarriesNoForceAcrossThePatch) {
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    const double v0 = 5.0;
    SolverOptions options;
    options.viscosity = {1.0, 1.0};
    options.hourglass = 0.1;
    options.precracks = {{Vec3(0.5, -0.1, -0.1), Vec3(0.0, 0.0, 0.6), Vec3(0.0, 0.8, 0.0)}};
    Simulation sim(latticeReference(gradedBoxMap(Vec3(1.0, 0.6, 0.4),
                                                 {AxisGrading{AxisGrading::Kind::OneSided, 1.5},
                                                  AxisGrading{}, AxisGrading{}}),
                                    3, {12, 8, 5}, steel.density, 1.2),
                   {HypoElastic(steel)}, options);
    const Reference& ref = sim.reference();
    sim.setVelocity([&](const Vec3& X) { return Vec3(X[0] < 0.5 ? -v0 : v0, 0.0, 0.0); });
    sim.start();
    const BrittleBonds& bonds = sim.integrator().bonds();
    ASSERT_TRUE(bonds.enabled());
    double worstF = 0.0;
    Index damaged = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        ASSERT_FALSE(bonds.detached(a)) << "particle " << a;
        if (!bonds.view(sim.state()).allIntact(a, a + 1)) ++damaged;
        worstF = std::max(
            worstF,
            (sim.state().F[static_cast<std::size_t>(a)] - Mat3::Identity()).cwiseAbs().maxCoeff());
    }
    // Every bond across x = 0.5 and no other: the brute force of the test above, in one line.
    Index across = 0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            if (b > a && (ref.X[static_cast<std::size_t>(a)][0] - 0.5) *
                                 (ref.X[static_cast<std::size_t>(b)][0] - 0.5) <
                             0.0)
                ++across;
        }
    EXPECT_EQ(bonds.brokenPairs(), across);
    EXPECT_LT(worstF, 1e-12);
    for (int i = 0; i < 50; ++i) sim.step();
    double worstV = 0.0, worstStress = 0.0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const Vec3 expected(ref.X[ia][0] < 0.5 ? -v0 : v0, 0.0, 0.0);
        worstV = std::max(worstV, (sim.state().v[ia] - expected).norm());
        worstStress = std::max(worstStress, sim.state().cauchy[ia].cwiseAbs().maxCoeff());
    }
    std::printf(
        "[bonds] precracked block: %d pairs cut, %d damaged particles; F = I to %.1e at t = 0; "
        "after 50 steps (%.2e s): |v − v0| ≤ %.1e m/s, |σ| ≤ %.1e Pa\n",
        bonds.brokenPairs(), damaged, worstF, sim.state().time, worstV, worstStress);
    EXPECT_GT(sim.state().time, 0.0);
    EXPECT_LT(worstV, 1e-9 * v0);
    EXPECT_LT(worstStress, 1e-12 * steel.youngsModulus);  // round-off of F = I, times E
    EXPECT_EQ(bonds.brokenPairs(), across);               // εmax = 0: nothing else breaks
}

// The cut rule (FailedBondRule::Cut): a layer of failed particles one wide, narrower than the
// kernel support (2.4 cells), cuts every bond across it, and no bond between two sound particles
// on one side; both directions of a pair agree; the two sides end in different pieces. With
// Either the same layer leaves the bonds that span it (sound particle to sound particle), which
// is what keeps a plug tied to its plate (docs/theory.md "Plate perforation"). A second call, or
// a fresh BrittleBonds attached to the cut state (a restart), cuts nothing more.
//
// The same on a stretched lattice (cells 0.1 × 0.3 × 0.1, as the rings of an O-grid graded
// radially): the cut is measured in the failed particle's own cells, so the bonds that cross
// the layer between two of its particles, 0.15 from each along y, are cut too (a sphere of 0.6 of
// the smallest spacing, 0.06, left them).
class CutRuleOnALattice : public ::testing::TestWithParam<double> {};

TEST_P(CutRuleOnALattice, SeversEveryBondAcrossAOneWideFailedLayer) {
    const double width = GetParam();  // along y, 6 cells
    const Reference ref =
        testing::builtReference(gradedBoxMap(Vec3(1.0, width, 0.4), {}), 3, {10, 6, 4});
    const auto n = static_cast<std::size_t>(ref.size());
    const auto layer = [&](std::size_t a) { return std::abs(ref.X[a][0] - 0.45) < 0.01; };
    const auto side = [&](std::size_t a) {
        return ref.X[a][0] < 0.4 ? -1 : ref.X[a][0] > 0.5 ? 1 : 0;
    };
    const auto cutState = [&](FailedBondRule rule, Index& fresh, Index& again) {
        State state = State::atRest(ref.X, static_cast<std::size_t>(ref.pairs.pairs()));
        state.dt = 1e-7;
        for (std::size_t a = 0; a < n; ++a)
            if (layer(a)) state.damage[a] = 1.0;
        BrittleBonds bonds(ref, std::vector<double>(n, 0.0), std::vector<FailedBondRule>(n, rule));
        bonds.attach(state);
        fresh = bonds.breakStretchedBonds(state).pairs;
        again = bonds.breakStretchedBonds(state).pairs;
        BrittleBonds resumed(ref, std::vector<double>(n, 0.0),
                             std::vector<FailedBondRule>(n, rule));
        resumed.attach(state);
        again += resumed.breakStretchedBonds(state).pairs;
        for (std::size_t a = 0; a < n; ++a)
            if (layer(a)) {
                EXPECT_TRUE(bonds.detached(static_cast<Index>(a))) << a;
            }
        return state.bondIntact;
    };
    for (const FailedBondRule rule : {FailedBondRule::Cut, FailedBondRule::Either}) {
        Index fresh = 0, again = 0;
        const std::vector<std::uint8_t> intact = cutState(rule, fresh, again);
        Index across = 0, sameSideBroken = 0, asymmetric = 0, failedKept = 0;
        for (Index a = 0; a < ref.size(); ++a)
            for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
                const auto ia = static_cast<std::size_t>(a);
                const auto b =
                    static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
                const bool holds = intact[static_cast<std::size_t>(k)] != 0;
                if (holds && side(ia) * side(b) < 0) ++across;
                if (!holds && side(ia) == side(b) && side(ia) != 0) ++sameSideBroken;
                if (holds && (layer(ia) || layer(b))) ++failedKept;
                for (Index m = ref.pairs.begin(static_cast<Index>(b));
                     m < ref.pairs.end(static_cast<Index>(b)); ++m)
                    if (ref.pairs.neighbor[static_cast<std::size_t>(m)] == a &&
                        intact[static_cast<std::size_t>(m)] != intact[static_cast<std::size_t>(k)])
                        ++asymmetric;
            }
        const std::vector<Index> piece = bondPieces(ref, intact);
        Index leftRoot = -1, rightRoot = -1;
        for (std::size_t a = 0; a < n; ++a) {
            if (side(a) < 0) leftRoot = piece[a];
            if (side(a) > 0) rightRoot = piece[a];
        }
        std::printf(
            "[bonds] one-wide failed layer, cells 0.1 x %.2f x 0.1, %s: %d pairs broken, %d "
            "entries across still intact, %d broken on one side\n",
            width / 6.0, rule == FailedBondRule::Cut ? "cut" : "either", fresh, across,
            sameSideBroken);
        EXPECT_EQ(failedKept, 0);
        EXPECT_EQ(asymmetric, 0);
        EXPECT_EQ(sameSideBroken, 0);
        EXPECT_EQ(again, 0) << "a second call or a restart cut more";
        if (rule == FailedBondRule::Cut) {
            EXPECT_EQ(across, 0) << "bonds across the failed layer survive the cut";
            EXPECT_NE(leftRoot, rightRoot) << "the two sides are still one piece";
        } else {
            EXPECT_GT(across, 0);  // Either: the bonds spanning the layer hold
            EXPECT_EQ(leftRoot, rightRoot);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(BrittleBonds, CutRuleOnALattice, ::testing::Values(0.6, 1.8),
                         [](const ::testing::TestParamInfo<double>& param) {
                             return param.param < 1.0 ? std::string("CubicCells")
                                                      : std::string("StretchedCells");
                         });

// Ductile fracture: with FailedBondRule::Either, every bond of a Johnson–Cook particle
// breaks once its damage reaches 1. A steel bar (Weldox 460E strength, damage constants scaled
// down so that it fails within a short pull: εf ≈ 0.15 at σ* = 1/3; 10 × 2 × 2 mm, 25 × 5 × 5
// particles) is pulled apart at ±20 m/s from its end layers. Claims: the bar comes apart (no
// path of intact bonds joins its ends) where particles failed; every broken bond has a failed
// end, every failed particle is detached (no bond left, no stress); no particle is removed and
// none inverts; the ledger's total (kinetic + elastic + plastic + damage + fracture + viscous +
// hourglass − boundary work) stays within 1 % of the energy moved. Without the option the same
// pull breaks no bond.
struct DuctileBar {
    bool apart = false;
    Index broken = 0, detached = 0, failed = 0;
    Index brokenWithoutFailedEnd = 0, failedWithBonds = 0;
    double worstImbalance = 0.0, scale = 0.0;
    EnergyReport energy;
};

DuctileBar pullDuctileBar(FailedBondRule rule) {
    testing::PulledWeldoxBar bar({rule});
    Simulation& sim = bar.sim;
    const Reference& ref = sim.reference();
    const std::vector<Index>&left = bar.left, &right = bar.right;
    const auto endsApart = [&](const State& s) {
        const std::vector<Index> piece = bondPieces(ref, s.bondIntact);
        return piece[static_cast<std::size_t>(left.front())] !=
               piece[static_cast<std::size_t>(right.front())];
    };
    sim.start();
    const EnergyReport e0 = sim.energy();
    DuctileBar out;
    out.scale = e0.kinetic;
    double apartAt = -1.0;
    // 1 µs at a time until the ends are apart (or 60 µs), then 5 µs more.
    for (int k = 1; k <= 60 && (apartAt < 0.0 || sim.state().time < apartAt + 5e-6); ++k) {
        sim.advanceTo(k * 1e-6);
        const EnergyReport e = sim.energy();
        out.scale = std::max(out.scale, e.boundaryWork);
        out.worstImbalance = std::max(out.worstImbalance, std::abs(e.total() - e0.total()));
        if (apartAt < 0.0 && endsApart(sim.state())) apartAt = sim.state().time;
    }
    const State& s = sim.state();
    out.apart = endsApart(s);
    out.energy = sim.energy();
    out.broken = sim.integrator().bonds().brokenPairs();
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const bool failed = s.damage[ia] >= 1.0;
        if (failed) ++out.failed;
        if (sim.integrator().bonds().detached(a)) ++out.detached;
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto b =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            const bool intact = s.bondIntact[static_cast<std::size_t>(k)] != 0;
            if (!intact && !failed && s.damage[b] < 1.0) ++out.brokenWithoutFailedEnd;
            if (intact && failed) ++out.failedWithBonds;
        }
    }
    std::printf(
        "[bonds] ductile bar (failed_bonds %s): t = %.1f µs, %d failed, %d "
        "detached, %d pairs broken, ends %s; boundary work %.4f J, plastic %.4f, damage %.5f, "
        "fracture %.5f, viscous %.4f J; worst imbalance %.2e of the energy moved\n",
        rule == FailedBondRule::Keep     ? "keep"
        : rule == FailedBondRule::Either ? "either"
                                         : "cut",
        1e6 * s.time, out.failed, out.detached, out.broken, out.apart ? "apart" : "joined",
        out.energy.boundaryWork, out.energy.plasticWork, out.energy.damageDissipation,
        out.energy.fractureEnergy, out.energy.viscousWork, out.worstImbalance / out.scale);
    return out;
}

TEST(BrittleBonds, FailedParticlesLoseTheirBondsAndTheDuctileBarComesApart) {
    const DuctileBar bar = pullDuctileBar(FailedBondRule::Either);
    EXPECT_GT(bar.failed, 0);
    EXPECT_TRUE(bar.apart) << "the two ends are still joined";
    EXPECT_GT(bar.broken, 0);
    EXPECT_EQ(bar.brokenWithoutFailedEnd, 0) << "a bond broke between two sound particles";
    EXPECT_EQ(bar.failedWithBonds, 0) << "a failed particle kept a bond";
    EXPECT_GE(bar.detached, bar.failed);
    EXPECT_LT(bar.worstImbalance, 1e-2 * bar.scale);
    const DuctileBar kept = pullDuctileBar(FailedBondRule::Keep);
    EXPECT_GT(kept.failed, 0);
    EXPECT_EQ(kept.broken, 0);
    EXPECT_FALSE(kept.apart);
    EXPECT_EQ(kept.energy.fractureEnergy, 0.0);
}

// The same pull with the cut rule: the bar comes apart, nothing inverts (the run would throw),
// every failed particle is detached, and the ledger closes as with Either.
TEST(BrittleBonds, CutRuleBarComesApartWithTheLedgerClosed) {
    const DuctileBar bar = pullDuctileBar(FailedBondRule::Cut);
    EXPECT_GT(bar.failed, 0);
    EXPECT_TRUE(bar.apart) << "the two ends are still joined";
    EXPECT_EQ(bar.failedWithBonds, 0) << "a failed particle kept a bond";
    EXPECT_GE(bar.detached, bar.failed);
    EXPECT_LT(bar.worstImbalance, 1e-2 * bar.scale);
}

}  // namespace
}  // namespace gsph
