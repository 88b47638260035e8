// SPDX-License-Identifier: MIT
// The split of a run over processes (distributed/halo_plan.hpp) on two overset blocks of
// spacing 1:2, band included: the cuts fall between blocks or split a strided one, and share
// the cost; each process receives exactly the other processes' particles its own read (pairs
// and transposed cross pairs, or a relation of its own), and what one sends another is what
// that one receives.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.hpp"
#include "distributed/halo_plan.hpp"
#include "support/overset_fixtures.hpp"

namespace gsph {
namespace {

struct Split {
    Reference ref = testing::twoBlocks(2, 8, 2).ref;
    StencilBlocks blocks = buildStencilBlocks(ref.pairs, 0, ref.size(), ref.oversetCoupled);
};

// Per particle index c: the cost of the particles below c, and whether a cut at c is allowed
// (no block of consecutive particles straddles it; every part of a strided block it splits,
// up to the block's ends or the previous cut, is at least a strip, kMinStencilRun), from the
// blocks' particles one by one.
struct CutRules {
    CutRules(const StencilBlocks& b, bool strided) : blocks(b), cutStrided(strided) {}
    std::ptrdiff_t costBefore(Index c) const {
        std::ptrdiff_t cost = 0;
        for (const ParticleBlock& b : blocks.blocks)
            for (Index i = 0; i < b.size(); ++i)
                if (b.particle(i) < c) cost += b.stencil == kNoStencil ? 4 : 1;
        return cost;
    }
    // After the cut `previous`, also no part of a strided block between the two shorter.
    bool allowed(Index previous, Index c) const {
        for (const ParticleBlock& b : blocks.blocks) {
            Index below = 0, between = 0;
            for (Index i = 0; i < b.size(); ++i) {
                below += b.particle(i) < c ? 1 : 0;
                between += b.particle(i) >= previous && b.particle(i) < c ? 1 : 0;
            }
            if (below == 0 || below == b.size()) continue;
            if (b.stride == 1 || !cutStrided) return false;
            if (below < kMinStencilRun || b.size() - below < kMinStencilRun) return false;
            if (between > 0 && between < kMinStencilRun) return false;
        }
        return true;
    }
    const StencilBlocks& blocks;
    bool cutStrided;
};

// Each cut is the first allowed place at or past its share of the cost: found here by trying
// every particle index. The fixture's corner columns are strided blocks, and some cut splits one;
// told to keep them whole, no cut does.
TEST(HaloPlan, EachCutIsTheFirstAllowedPlacePastItsShareOfTheCost) {
    const Split s;
    ASSERT_FALSE(s.ref.crossPair.empty()) << "the fixture has an overset band";
    const Index n = s.ref.size();
    const std::ptrdiff_t total = s.blocks.cost.back();
    bool splitsAStridedBlock = false;
    for (const bool cutStrided : {true, false})
        for (int processes : {1, 2, 3, 5, 7}) {
            const CutRules rules(s.blocks, cutStrided);
            const std::vector<Index> cuts = cutByCost({s.blocks}, n, processes, cutStrided);
            ASSERT_EQ(cuts.size(), static_cast<std::size_t>(processes) + 1);
            EXPECT_EQ(cuts.front(), 0);
            EXPECT_EQ(cuts.back(), n);
            for (int r = 1; r < processes; ++r) {
                const std::ptrdiff_t share = total * r / processes;
                Index expected = cuts[static_cast<std::size_t>(r) - 1] + 1;
                while (!rules.allowed(cuts[static_cast<std::size_t>(r) - 1], expected) ||
                       rules.costBefore(expected) < share)
                    ++expected;
                const Index cut = cuts[static_cast<std::size_t>(r)];
                EXPECT_EQ(cut, expected) << processes << " processes, cut " << r;
                for (const ParticleBlock& b : s.blocks.blocks)
                    if (b.stride > 1 && b.begin < cut && cut < b.end) {
                        EXPECT_TRUE(cutStrided) << "a strided block cut though it must stay whole";
                        splitsAStridedBlock = true;
                    }
            }
            // Each process's cost, and its blocks' parts (ParticleBlock::within) cover its range.
            const std::vector<std::ptrdiff_t> costs = costsOf({s.blocks}, cuts);
            std::ptrdiff_t sum = 0;
            for (int r = 0; r < processes; ++r) {
                const auto ir = static_cast<std::size_t>(r);
                EXPECT_EQ(costs[ir], rules.costBefore(cuts[ir + 1]) - rules.costBefore(cuts[ir]));
                sum += costs[ir];
                std::vector<int> covered(static_cast<std::size_t>(n), 0);
                for (const ParticleBlock& whole : s.blocks.blocks) {
                    const ParticleBlock part = whole.within(cuts[ir], cuts[ir + 1]);
                    EXPECT_TRUE(part.size() == 0 || part.stencil == kNoStencil ||
                                part.size() >= kMinStencilRun)
                        << "block " << whole.begin << ".." << whole.end << " stride "
                        << whole.stride << " part " << part.begin << ".." << part.end << " cuts "
                        << cuts[ir] << ", " << cuts[ir + 1];
                    for (Index i = 0; i < part.size(); ++i)
                        ++covered[static_cast<std::size_t>(part.particle(i))];
                }
                for (Index a = 0; a < n; ++a)
                    EXPECT_EQ(covered[static_cast<std::size_t>(a)],
                              a >= cuts[ir] && a < cuts[ir + 1] ? 1 : 0)
                        << "particle " << a << ", process " << r;
            }
            EXPECT_EQ(sum, total);
        }
    EXPECT_TRUE(splitsAStridedBlock) << "no cut fell inside a strided block: the test is idle";
}

TEST(HaloPlan, EachProcessReceivesWhatItsParticlesReadAndSendsWhatTheOthersRead) {
    const Split s;
    const Reference& ref = s.ref;
    const int processes = 3;
    const std::vector<Index> cuts = cutByCost({s.blocks}, ref.size(), processes);
    std::vector<std::vector<HaloPeer>> plans;
    for (int p = 0; p < processes; ++p) plans.push_back(planHalo(pairReads(ref), cuts, p));
    for (int p = 0; p < processes; ++p) {
        const Index lo = cuts[static_cast<std::size_t>(p)];
        const Index hi = cuts[static_cast<std::size_t>(p) + 1];
        std::set<Index> reads;
        for (Index a = lo; a < hi; ++a) {
            for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k)
                reads.insert(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            for (Index k = ref.crossOffset[static_cast<std::size_t>(a)];
                 k < ref.crossOffset[static_cast<std::size_t>(a) + 1]; ++k)
                reads.insert(ref.crossOwner[static_cast<std::size_t>(k)]);
        }
        std::set<Index> expected, received;
        for (Index b : reads)
            if (b < lo || b >= hi) expected.insert(b);
        for (const HaloPeer& peer : plans[static_cast<std::size_t>(p)]) {
            const Index qlo = cuts[static_cast<std::size_t>(peer.process)];
            const Index qhi = cuts[static_cast<std::size_t>(peer.process) + 1];
            EXPECT_TRUE(std::is_sorted(peer.receive.begin(), peer.receive.end()));
            for (Index b : peer.receive) {
                EXPECT_TRUE(b >= qlo && b < qhi) << "received from a process that does not own it";
                received.insert(b);
            }
            // What the peer sends p is what p receives from it.
            const auto& theirs = plans[static_cast<std::size_t>(peer.process)];
            const auto back = std::find_if(theirs.begin(), theirs.end(),
                                           [&](const HaloPeer& h) { return h.process == p; });
            ASSERT_NE(back, theirs.end());
            EXPECT_EQ(back->send, peer.receive);
        }
        EXPECT_EQ(received, expected) << "process " << p;
        EXPECT_FALSE(expected.empty());
    }
}

TEST(HaloPlan, AHaloOfItsOwnFollowsItsRelationNotThePairs) {
    // A read beyond the pairs (a nonlocal average): particle a reads a ± 40 (further than any
    // pair on this layout), nothing else. Each process receives exactly those outside its range.
    const Split s;
    const Index n = s.ref.size();
    const Reads far = [n](Index a, std::vector<Index>& out) {
        for (Index b : {a - 40, a + 40})
            if (b >= 0 && b < n) out.push_back(b);
    };
    const int processes = 3;
    const std::vector<Index> cuts = cutByCost({s.blocks}, n, processes);
    for (int p = 0; p < processes; ++p) {
        const Index lo = cuts[static_cast<std::size_t>(p)];
        const Index hi = cuts[static_cast<std::size_t>(p) + 1];
        std::set<Index> expected, received;
        for (Index a = lo; a < hi; ++a)
            for (Index b : {a - 40, a + 40})
                if (b >= 0 && b < n && (b < lo || b >= hi)) expected.insert(b);
        for (const HaloPeer& peer : planHalo(far, cuts, p)) {
            received.insert(peer.receive.begin(), peer.receive.end());
            for (Index a : peer.send) {
                const Index qlo = cuts[static_cast<std::size_t>(peer.process)];
                const Index qhi = cuts[static_cast<std::size_t>(peer.process) + 1];
                EXPECT_TRUE((a - 40 >= qlo && a - 40 < qhi) || (a + 40 >= qlo && a + 40 < qhi))
                    << "sent " << a << " to process " << peer.process << ", which does not read it";
            }
        }
        EXPECT_EQ(received, expected) << "process " << p;
        EXPECT_FALSE(expected.empty());
    }
}

TEST(HaloPlan, MoreProcessesThanBlocksAreRefused) {
    const Split s;
    EXPECT_THROW(cutByCost({s.blocks}, s.ref.size(), s.ref.size() + 1), InputError);
    EXPECT_THROW(cutByCost({s.blocks}, s.ref.size(), 0), InputError);
}

}  // namespace
}  // namespace gsph
