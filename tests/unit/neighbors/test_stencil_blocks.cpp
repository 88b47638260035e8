// SPDX-License-Identifier: MIT
// The partition of a body into stencil blocks (neighbors/stencil_blocks.hpp): every particle in
// exactly one block, each stencil block's particles have exactly its stencil as their list, and
// on a lattice only the corners of the box are left to the CSR path (the faces normal to the
// fastest index form blocks across rows, unless they would cut the rows of particles flagged for
// the CSR path into pieces).
#include <gtest/gtest.h>

#include <vector>

#include "neighbors/stencil_blocks.hpp"
#include "neighbors/theta_search.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

Reference box(std::array<int, 3> cells) {
    Reference ref = latticeReference(
        gradedBoxMap(Vec3(1, 1, 1),
                     {AxisGrading{AxisGrading::Kind::OneSided, 4.0}, AxisGrading{}, AxisGrading{}}),
        3, cells, 1000.0, 1.2);
    buildPairs(ref);
    return ref;
}

TEST(StencilBlocks, PartitionHoldsTheStencilInvariant) {
    const std::array<int, 3> cells{13, 11, 9};
    const Reference ref = box(cells);
    const PairList& P = ref.pairs;
    const StencilBlocks sb = buildStencilBlocks(P, 0, ref.size());
    EXPECT_EQ(sb.particles, ref.size());
    std::vector<int> seen(static_cast<std::size_t>(ref.size()), 0);
    Index csr = 0, strided = 0, previousBegin = -1;
    for (const ParticleBlock& b : sb.blocks) {
        EXPECT_GT(b.begin, previousBegin);  // sorted by first particle
        previousBegin = b.begin;
        EXPECT_GE(b.stride, 1);
        EXPECT_LE(b.size(), kMaxBlock);
        EXPECT_EQ(b.particle(b.size() - 1), b.end - 1);
        if (b.stencil == kNoStencil) {
            EXPECT_EQ(b.stride, 1);
            csr += b.size();
        } else {
            EXPECT_GE(b.size(), kMinStencilRun);
            if (b.stride > 1) strided += b.size();
        }
        for (Index i = 0; i < b.size(); ++i) {
            const Index a = b.particle(i);
            ++seen[static_cast<std::size_t>(a)];
            if (b.stencil == kNoStencil) continue;
            const Stencil& st = sb.stencils[static_cast<std::size_t>(b.stencil)];
            ASSERT_EQ(P.end(a) - P.begin(a), st.size());
            for (Index k = 0; k < st.size(); ++k) {
                const auto ik = static_cast<std::size_t>(P.begin(a) + k);
                EXPECT_EQ(P.neighbor[ik], a + st.delta[static_cast<std::size_t>(k)]);
                EXPECT_EQ(P.kernelId[ik], st.kernelId[static_cast<std::size_t>(k)]);
            }
        }
    }
    for (const int n : seen) EXPECT_EQ(n, 1);
    // κ = 1.2: the support reaches two cells, so a particle is "near a wall" in 4 of the n
    // positions of an axis. Left to CSR: the particles near a wall in all three axes (the box's
    // corners), 4³ = 64 of them.
    EXPECT_EQ(csr, 64);
    // Across rows: near a wall in the fastest axis, not in both others.
    EXPECT_EQ(strided, 4 * (cells[1] * cells[2] - 16));
}

TEST(StencilBlocks, FlaggedParticlesStayOnTheCsrPath) {
    const Reference ref = box({10, 10, 10});
    std::vector<std::uint8_t> csrOnly(static_cast<std::size_t>(ref.size()), 0);
    for (Index a = 0; a < ref.size(); a += 7) csrOnly[static_cast<std::size_t>(a)] = 1;
    const StencilBlocks sb = buildStencilBlocks(ref.pairs, 0, ref.size(), csrOnly);
    Index onStencils = 0;
    for (const ParticleBlock& b : sb.blocks) {
        if (b.stencil != kNoStencil) onStencils += b.size();
        for (Index i = 0; i < b.size(); ++i)
            if (csrOnly[static_cast<std::size_t>(b.particle(i))] != 0) {
                EXPECT_EQ(b.stencil, kNoStencil) << "particle " << b.particle(i);
            }
    }
    EXPECT_GT(onStencils, ref.size() / 4);  // the rest still share stencils
}

// An annulus-like body: in every row of 10 the first 8 particles are flagged (an overset band),
// the last 2 lie near the wall normal to the fastest index and would share a stencil across
// rows. Taken into strided blocks they would cut the flagged rows into blocks of 8; left to the
// CSR path, all the particles are one CSR run, split into ⌈1000 / kMaxBlock⌉ blocks.
TEST(StencilBlocks, RunsAcrossRowsLeaveTheCsrRowsWhole) {
    const Reference ref = box({10, 10, 10});
    std::vector<std::uint8_t> csrOnly(static_cast<std::size_t>(ref.size()), 0);
    for (Index a = 0; a < ref.size(); ++a) csrOnly[static_cast<std::size_t>(a)] = a % 10 < 8;
    const StencilBlocks sb = buildStencilBlocks(ref.pairs, 0, ref.size(), csrOnly);
    Index csr = 0, csrBlocks = 0;
    for (const ParticleBlock& b : sb.blocks)
        if (b.stencil == kNoStencil) csr += b.size(), ++csrBlocks;
    EXPECT_EQ(csr, ref.size());
    EXPECT_EQ(csrBlocks, (ref.size() + kMaxBlock - 1) / kMaxBlock);
    // Without flags the same two columns do form blocks across rows.
    const StencilBlocks plain = buildStencilBlocks(ref.pairs, 0, ref.size());
    Index strided = 0;
    for (const ParticleBlock& b : plain.blocks)
        if (b.stencil != kNoStencil && b.stride > 1) strided += b.size();
    EXPECT_GT(strided, 0);
}

}  // namespace
}  // namespace gsph
