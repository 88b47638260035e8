// SPDX-License-Identifier: MIT
// The CSR path of the internal force and of F's θ-gradients runs in SIMD lanes from staged pairs
// (neighbors/staged_pairs.hpp): staged once (masked strips and gathered runs) or staged at each
// call (gathered runs), the runs' far ends gathered from the SoA fields or read as rows
// (neighbors/pair_field_rows.hpp). On two overset blocks (cross pairs, interface corrections,
// mirrors) with every particle on the CSR path and random fields, each gives the same bits at
// every strip width (rows or not), and each equals the pair formulas of DESIGN §4 summed one pair
// at a time (written out here) to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "core/lanes.hpp"
#include "failure/brittle_bonds.hpp"
#include "forces/internal_force.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "support/overset_fixtures.hpp"

namespace gsph {
namespace {

struct Fixture {
    testing::TwoBlocks t = testing::twoBlocks(3, 5, 2);
    ParticleFields fields;
    StressFactors factors;
    StencilBlocks blocks;
    ForceOptions options;

    explicit Fixture(HourglassModulus modulus) {
        Reference& ref = t.ref;
        const auto n = static_cast<std::size_t>(ref.size());
        ref.oversetCoupled.assign(n, 1);  // every particle on the CSR path
        blocks = buildStencilBlocks(ref.pairs, 0, ref.size(), ref.oversetCoupled);
        fields.resize(n);
        factors.resize(n);
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const auto mat = [&](double scale) {
            Mat3 m;
            for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = scale * u(random);
            return m;
        };
        const double h = t.fine;
        for (std::size_t a = 0; a < n; ++a) {
            fields.X.set(a, ref.X[a]);
            fields.x.set(a, Vec3(ref.X[a] + 0.2 * h * Vec3(u(random), u(random), u(random))));
            fields.v.set(a, Vec3(50.0 * Vec3(u(random), u(random), u(random))));
            fields.F.set(a, Mat3(Mat3::Identity() + mat(0.1)));
            factors.K.set(a, mat(1e3));
            factors.N.set(a, mat(1e-5));
            factors.soundSpeed[a] = 5000.0 + 100.0 * u(random);
            factors.density[a] = 7800.0 + 50.0 * u(random);
            factors.viscositySwitch[a] = 0.5 + 0.5 * u(random);
            factors.hourglassScale[a] = 0.6 + 0.4 * u(random);
        }
        options.viscosity = {1.0, 1.0, 0.01};
        options.hourglass = 0.1;
        options.youngsModulus = 200e9;
        options.hourglassModulus = modulus;
    }

    std::vector<Vec3> force(const CsrPairWeights* staged, ForceParts& parts,
                            const BondView& bonds = {}, const Mat3* G = nullptr,
                            PairFieldRows* rows = nullptr) const {
        const auto n = static_cast<std::size_t>(t.ref.size());
        std::vector<Vec3> f(n);
        parts.viscous.assign(n, Vec3::Zero());
        parts.hourglass.assign(n, Vec3::Zero());
        if (rows != nullptr) {
            refreshReferenceRows(*rows, fields, *staged, n);
            refreshMotionRows(*rows, fields, *staged, n);
        }
        internalForce(t.ref, fields, factors, blocks, options, f, parts, bonds, G, staged, rows);
        return f;
    }

    // The pair formulas one pair at a time, in list order (DESIGN §4, §6).
    std::vector<Vec3> reference() const {
        const Reference& ref = t.ref;
        const PairList& P = ref.pairs;
        const double alphaE = options.hourglass * options.youngsModulus;
        const bool secant = options.hourglassModulus == HourglassModulus::Secant;
        std::vector<Vec3> out(static_cast<std::size_t>(ref.size()));
        const auto viscous = [&](std::size_t c, std::size_t b) {
            const Vec3 xcb = fields.x[c] - fields.x[b];
            return viscousPairPressure(
                options.viscosity, (fields.v[c] - fields.v[b]).dot(xcb), xcb.squaredNorm(),
                0.5 * (ref.smoothingLength[c] + ref.smoothingLength[b]),
                0.5 * (factors.soundSpeed[c] + factors.soundSpeed[b]),
                0.5 * (factors.density[c] + factors.density[b]),
                0.5 * (factors.viscositySwitch[c] + factors.viscositySwitch[b]));
        };
        const auto hourglass = [&](std::size_t c, std::size_t b, double W) {
            double weight = 0.5 * (ref.quadVolume[c] + ref.quadVolume[b]) * W;
            if (secant) weight *= 0.5 * (factors.hourglassScale[c] + factors.hourglassScale[b]);
            return hourglassPairForce(alphaE, fields.F[c], fields.F[b], ref.X[b] - ref.X[c],
                                      fields.x[b] - fields.x[c], weight);
        };
        for (Index c = 0; c < ref.size(); ++c) {
            const auto ic = static_cast<std::size_t>(c);
            Vec3 sumW = Vec3::Zero(), fK = Vec3::Zero(), sumQW = Vec3::Zero(), fN = Vec3::Zero(),
                 fh = Vec3::Zero();
            const Vec3* own = ref.pairCorrections(c);
            const Vec3* mirror = ref.mirrorCorrections(c);
            for (Index k = P.begin(c); k < P.end(c); ++k) {
                const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
                const KernelEntry& e = P.table[P.kernelId[static_cast<std::size_t>(k)]];
                const auto slot = static_cast<std::size_t>(k - P.begin(c));
                const bool across = ref.space[b] != ref.space[ic];
                sumW += own != nullptr ? Vec3(e.gradW + own[slot]) : e.gradW;
                if (!across)
                    fK +=
                        factors.K[b] * (mirror != nullptr ? Vec3(e.gradW - mirror[slot]) : e.gradW);
                const double q = viscous(ic, b);
                sumQW += q * e.gradW;
                if (!across) fN += q * (factors.N[b] * e.gradW);
                fh += (across ? 0.5 : 1.0) * hourglass(ic, b, e.W);
            }
            for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot) {
                const Index k = ref.crossPair[static_cast<std::size_t>(slot)];
                const Index owner = ref.crossOwner[static_cast<std::size_t>(slot)];
                const auto b = static_cast<std::size_t>(owner);
                const KernelEntry& e = P.table[P.kernelId[static_cast<std::size_t>(k)]];
                const Vec3* correction = ref.pairCorrections(owner);
                fK -= factors.K[b] * (correction != nullptr
                                          ? Vec3(e.gradW + correction[k - P.begin(owner)])
                                          : e.gradW);
                fN -= viscous(ic, b) * (factors.N[b] * e.gradW);
                fh += 0.5 * hourglass(ic, b, e.W);
            }
            out[ic] = factors.K[ic] * sumW + fK - (factors.N[ic] * sumQW + fN) + fh;
        }
        return out;
    }
};

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

class CsrPairLanes : public ::testing::TestWithParam<HourglassModulus> {};

double worstAgainst(const std::vector<Vec3>& reference, const std::vector<Vec3>& f) {
    double worst = 0.0, scale = 0.0;
    for (std::size_t a = 0; a < reference.size(); ++a) {
        worst = std::max(worst, (reference[a] - f[a]).norm());
        scale = std::max(scale, reference[a].norm());
    }
    return worst / scale;
}

TEST_P(CsrPairLanes, StagedOnceOrEachCallEqualThePairFormulasWithTheSameBitsAtEveryWidth) {
    const Fixture fx(GetParam());
    ASSERT_FALSE(fx.t.ref.crossPair.empty());
    ASSERT_FALSE(fx.t.ref.pairCorrection.empty());
    const CsrPairWeights staged = stageCsrPairs(fx.t.ref, fx.blocks);
    ASSERT_FALSE(staged.strips.empty()) << "the masked strips must be exercised";
    const std::vector<Vec3> plain = fx.reference();
    int widths = 0;
    for (const CsrPairWeights* w : {static_cast<const CsrPairWeights*>(nullptr), &staged}) {
        limitLanes(2);
        ForceParts parts2;
        const std::vector<Vec3> portable = fx.force(w, parts2);
        widths = 1;
        for (int width : {4, 8}) {
            limitLanes(width);
            if (laneWidth() < width) continue;
            ++widths;
            ForceParts parts;
            EXPECT_TRUE(sameBits(fx.force(w, parts), portable))
                << width << " lanes, staged " << (w != nullptr ? "once" : "each call");
            EXPECT_TRUE(sameBits(parts.viscous, parts2.viscous));
            EXPECT_TRUE(sameBits(parts.hourglass, parts2.hourglass));
        }
        if (w != nullptr)  // the runs' far ends read as rows: the same bits at every width
            for (int width : {2, 4, 8}) {
                limitLanes(width);
                if (laneWidth() < width) continue;
                PairFieldRows rows;
                ForceParts parts;
                EXPECT_TRUE(sameBits(fx.force(w, parts, {}, nullptr, &rows), portable))
                    << width << " lanes, rows";
                EXPECT_TRUE(sameBits(parts.viscous, parts2.viscous));
                EXPECT_TRUE(sameBits(parts.hourglass, parts2.hourglass));
            }
        limitLanes(8);
        const double worst = worstAgainst(plain, portable);
        std::printf(
            "[csr lanes] staged %s (%zu masked strips): against the pair formulas one "
            "pair at a time %.1e of max |f|\n",
            w != nullptr ? "once" : "each call", staged.strips.size(), worst);
        EXPECT_LT(worst, 3e-15);
    }
    EXPECT_EQ(staged.gathered.size(), static_cast<std::size_t>(fx.t.ref.size()))
        << "every particle is on the CSR path, so every one may be read";
    std::printf("[csr lanes] %d particles, %zu cross pairs: bit-identical at %d strip widths\n",
                fx.t.ref.size(), fx.t.ref.crossPair.size(), widths);
}

// Bonds broken in one corner of the fine block: only the particles whose own or whose
// neighbours' bonds broke (BondView::stale), and the masked strips holding one, stage their pairs
// afresh; the others read the weights staged once. The force is the one of staging every
// particle afresh to round-off, with the same bits at every width.
TEST(CsrPairLanes, OnlyParticlesNearABrokenBondStageTheirPairsAfresh) {
    const Fixture fx(HourglassModulus::Elastic);
    const Reference& ref = fx.t.ref;
    const CsrPairWeights staged = stageCsrPairs(ref, fx.blocks);
    State state = State::atRest(ref.X, static_cast<std::size_t>(ref.pairs.pairs()));
    const Vec3 corner = ref.X[0];
    const double cut = 1.5 * fx.t.fine;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto b =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            const bool nearA = (ref.X[static_cast<std::size_t>(a)] - corner).norm() < cut;
            if (nearA != ((ref.X[b] - corner).norm() < cut))
                state.bondIntact[static_cast<std::size_t>(k)] = 0;
        }
    BrittleBonds bonds(ref, std::vector<double>(static_cast<std::size_t>(ref.size()), 0.0), {},
                       true);
    bonds.attach(state);
    const BondView view = bonds.view(state);
    Index stale = 0;
    for (Index a = 0; a < ref.size(); ++a) stale += view.keepsStaged(a) ? 0 : 1;
    ASSERT_GT(stale, 0);
    ASSERT_LT(stale, ref.size() / 2) << "most particles must still read the staged weights";
    limitLanes(2);
    ForceParts parts;
    const std::vector<Vec3> afresh = fx.force(nullptr, parts, view, bonds.G().data());
    const std::vector<Vec3> portable = fx.force(&staged, parts, view, bonds.G().data());
    for (int width : {2, 4, 8}) {
        limitLanes(width);
        if (laneWidth() < width) continue;
        if (width > 2) {
            EXPECT_TRUE(sameBits(fx.force(&staged, parts, view, bonds.G().data()), portable))
                << width << " lanes";
        }
        PairFieldRows rows;
        EXPECT_TRUE(sameBits(fx.force(&staged, parts, view, bonds.G().data(), &rows), portable))
            << width << " lanes, rows";
    }
    limitLanes(8);
    const double worst = worstAgainst(afresh, portable);
    // F's θ-gradients over the surviving bonds likewise (from rows: the same bits).
    double worstGradient = 0.0;
    PairFieldRows rows;
    refreshMotionRows(rows, fx.fields, staged, static_cast<std::size_t>(ref.size()));
    for (const ParticleBlock& block : fx.blocks.blocks) {
        BlockThetaGradients once, each;
        csrThetaGradients(ref, &staged, view, block, fx.fields.x, fx.fields.v, once);
        csrThetaGradients(ref, nullptr, view, block, fx.fields.x, fx.fields.v, each);
        BlockThetaGradients fromRows;
        csrThetaGradients(ref, &staged, view, block, fx.fields.x, fx.fields.v, fromRows, &rows);
        for (Index i = 0; i < block.size(); ++i)
            EXPECT_TRUE(fromRows.gradX(i) == once.gradX(i) && fromRows.gradV(i) == once.gradV(i))
                << "θ-gradients from rows, particle " << block.particle(i);
        for (Index i = 0; i < block.size(); ++i)
            worstGradient = std::max(
                {worstGradient, (once.gradX(i) - each.gradX(i)).norm() / each.gradX(i).norm(),
                 (once.gradV(i) - each.gradV(i)).norm() / each.gradV(i).norm()});
    }
    std::printf(
        "[csr lanes] %d of %d particles stale: against staging every particle afresh %.1e "
        "of max |f|, θ-gradients %.1e\n",
        stale, ref.size(), worst, worstGradient);
    EXPECT_LT(worst, 1e-15);
    EXPECT_LT(worstGradient, 3e-14);
}

TEST(CsrPairLanes, ThetaGradientsAreTheListSumsWithTheSameBitsAtEveryWidth) {
    const Fixture fx(HourglassModulus::Elastic);
    const Reference& ref = fx.t.ref;
    const CsrPairWeights staged = stageCsrPairs(ref, fx.blocks);
    std::vector<Vec3> x(static_cast<std::size_t>(ref.size())), v(x.size());
    for (std::size_t a = 0; a < x.size(); ++a) x[a] = fx.fields.x[a], v[a] = fx.fields.v[a];
    const auto gradients = [&](int width, const CsrPairWeights* w,
                               const PairFieldRows* rows = nullptr) {
        limitLanes(width);
        std::vector<Mat3> g(2 * x.size());
        for (const ParticleBlock& block : fx.blocks.blocks) {
            BlockThetaGradients bg;
            csrThetaGradients(ref, w, {}, block, fx.fields.x, fx.fields.v, bg, rows);
            for (Index i = 0; i < block.size(); ++i) {
                const auto ia = static_cast<std::size_t>(block.particle(i));
                g[2 * ia] = bg.gradX(i), g[2 * ia + 1] = bg.gradV(i);
            }
        }
        limitLanes(8);
        return g;
    };
    for (const CsrPairWeights* w : {static_cast<const CsrPairWeights*>(nullptr), &staged}) {
        const std::vector<Mat3> portable = gradients(2, w);
        for (int width : {4, 8}) {
            const std::vector<Mat3> wide = gradients(width, w);
            EXPECT_EQ(std::memcmp(wide.data(), portable.data(), wide.size() * sizeof(Mat3)), 0)
                << width << " lanes";
        }
        if (w != nullptr) {  // the far ends' x and v read as rows: the same bits at every width
            PairFieldRows rows;
            refreshMotionRows(rows, fx.fields, *w, x.size());
            for (int width : {2, 4, 8}) {
                if (laneWidth() < width) continue;
                const std::vector<Mat3> fromRows = gradients(width, w, &rows);
                EXPECT_EQ(
                    std::memcmp(fromRows.data(), portable.data(), fromRows.size() * sizeof(Mat3)),
                    0)
                    << width << " lanes, rows";
            }
        }
        double worst = 0.0;
        for (Index a = 0; a < ref.size(); ++a) {
            const auto ia = static_cast<std::size_t>(a);
            Mat3 gradX, gradV;
            thetaGradients(ref, a, x.data(), v.data(), gradX, gradV, nullptr,
                           ref.pairCorrections(a));
            worst =
                std::max({worst, (gradX - portable[2 * ia]).cwiseAbs().maxCoeff() / gradX.norm(),
                          (gradV - portable[2 * ia + 1]).cwiseAbs().maxCoeff() / gradV.norm()});
        }
        std::printf("[csr lanes] θ-gradients staged %s against the list sums: %.1e\n",
                    w != nullptr ? "once" : "each call", worst);
        EXPECT_LT(worst, 3e-14);
    }
}

INSTANTIATE_TEST_SUITE_P(HourglassModulus, CsrPairLanes,
                         ::testing::Values(HourglassModulus::Elastic, HourglassModulus::Secant),
                         [](const auto& param) {
                             return param.param == HourglassModulus::Secant ? "Secant" : "Elastic";
                         });

}  // namespace
}  // namespace gsph
