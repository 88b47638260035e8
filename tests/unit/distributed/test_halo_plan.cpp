// SPDX-License-Identifier: MIT
// The split of a run over processes (distributed/halo_plan.hpp) on two overset blocks of
// spacing 1:2, band included: the cuts fall between blocks and share the cost; each process
// receives exactly the other processes' particles its own read (pairs and transposed cross
// pairs), and what one sends another is what that one receives.
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

// Each cut is the first place at or past its share of the cost where no block straddles it:
// found here by trying every particle index.
TEST(HaloPlan, EachCutIsTheFirstPlaceBetweenBlocksPastItsShareOfTheCost) {
    const Split s;
    ASSERT_FALSE(s.ref.crossPair.empty()) << "the fixture has an overset band";
    const Index n = s.ref.size();
    const std::ptrdiff_t total = s.blocks.cost.back();
    const auto costBefore = [&](Index c) {
        std::ptrdiff_t cost = 0;
        for (std::size_t k = 0; k < s.blocks.blocks.size(); ++k)
            if (s.blocks.blocks[k].end <= c) cost += s.blocks.cost[k + 1] - s.blocks.cost[k];
        return cost;
    };
    const auto straddled = [&](Index c) {
        for (const ParticleBlock& b : s.blocks.blocks)
            if (b.begin < c && c < b.end) return true;
        return false;
    };
    for (int processes : {1, 2, 3, 5}) {
        const std::vector<Index> cuts = cutByCost({s.blocks}, n, processes);
        ASSERT_EQ(cuts.size(), static_cast<std::size_t>(processes) + 1);
        EXPECT_EQ(cuts.front(), 0);
        EXPECT_EQ(cuts.back(), n);
        for (int r = 1; r < processes; ++r) {
            const std::ptrdiff_t share = total * r / processes;
            Index expected = cuts[static_cast<std::size_t>(r) - 1] + 1;
            while (straddled(expected) || costBefore(expected) < share) ++expected;
            EXPECT_EQ(cuts[static_cast<std::size_t>(r)], expected)
                << processes << " processes, cut " << r;
        }
        const std::vector<std::ptrdiff_t> costs = costsOf({s.blocks}, cuts);
        std::ptrdiff_t sum = 0;
        for (int r = 0; r < processes; ++r) {
            const auto ir = static_cast<std::size_t>(r);
            EXPECT_EQ(costs[ir], costBefore(cuts[ir + 1]) - costBefore(cuts[ir]));
            sum += costs[ir];
        }
        EXPECT_EQ(sum, total);
    }
}

TEST(HaloPlan, EachProcessReceivesWhatItsParticlesReadAndSendsWhatTheOthersRead) {
    const Split s;
    const Reference& ref = s.ref;
    const int processes = 3;
    const std::vector<Index> cuts = cutByCost({s.blocks}, ref.size(), processes);
    std::vector<std::vector<HaloPeer>> plans;
    for (int p = 0; p < processes; ++p) plans.push_back(planHalo(ref, cuts, p));
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

TEST(HaloPlan, MoreProcessesThanBlocksAreRefused) {
    const Split s;
    EXPECT_THROW(cutByCost({s.blocks}, s.ref.size(), s.ref.size() + 1), InputError);
    EXPECT_THROW(cutByCost({s.blocks}, s.ref.size(), 0), InputError);
}

}  // namespace
}  // namespace gsph
