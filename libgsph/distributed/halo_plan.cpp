// SPDX-License-Identifier: MIT
#include "distributed/halo_plan.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace gsph {
namespace {

struct Span {
    Index begin, end;
    std::ptrdiff_t cost;
};

// The particles outside [lo, hi) that the particles of [lo, hi) read, ascending.
std::vector<Index> readsOutside(const Reference& ref, Index lo, Index hi) {
    const PairList& P = ref.pairs;
    std::vector<Index> out;
    const auto outside = [&](Index b) {
        if (b < lo || b >= hi) out.push_back(b);
    };
    for (Index a = lo; a < hi; ++a) {
        for (Index k = P.begin(a); k < P.end(a); ++k)
            outside(P.neighbor[static_cast<std::size_t>(k)]);
        if (!ref.crossOffset.empty())
            for (Index k = ref.crossOffset[static_cast<std::size_t>(a)];
                 k < ref.crossOffset[static_cast<std::size_t>(a) + 1]; ++k)
                outside(ref.crossOwner[static_cast<std::size_t>(k)]);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<Index> within(const std::vector<Index>& sorted, Index lo, Index hi) {
    return {std::lower_bound(sorted.begin(), sorted.end(), lo),
            std::lower_bound(sorted.begin(), sorted.end(), hi)};
}

}  // namespace

std::vector<Index> cutByCost(const std::vector<StencilBlocks>& bodies, Index particles,
                             int processes) {
    if (processes < 1) throw InputError("a run needs at least one process");
    std::vector<Span> spans;
    for (const StencilBlocks& body : bodies)
        for (std::size_t k = 0; k < body.blocks.size(); ++k)
            spans.push_back(
                {body.blocks[k].begin, body.blocks[k].end, body.cost[k + 1] - body.cost[k]});
    std::sort(spans.begin(), spans.end(),
              [](const Span& a, const Span& b) { return a.begin < b.begin; });
    // Where a cut may go (no block straddles it) and the cost before it.
    std::vector<Index> position;
    std::vector<std::ptrdiff_t> before;
    std::ptrdiff_t total = 0;
    Index reach = 0;
    for (std::size_t k = 0; k < spans.size(); ++k) {
        total += spans[k].cost;
        reach = std::max(reach, spans[k].end);
        if (k + 1 == spans.size() || spans[k + 1].begin >= reach) {
            position.push_back(reach);
            before.push_back(total);
        }
    }
    std::vector<Index> cuts(static_cast<std::size_t>(processes) + 1, 0);
    cuts.back() = particles;
    std::size_t next = 0;
    for (int r = 1; r < processes; ++r) {
        const std::ptrdiff_t target = total * r / processes;
        const Index previous = cuts[static_cast<std::size_t>(r) - 1];
        while (next < position.size() && (before[next] < target || position[next] <= previous))
            ++next;
        if (next >= position.size() || position[next] >= particles)
            throw InputError(std::to_string(processes) + " processes for " +
                             std::to_string(particles) + " particles in " +
                             std::to_string(position.size()) +
                             " indivisible blocks: some process would own none; run on fewer");
        cuts[static_cast<std::size_t>(r)] = position[next];
    }
    return cuts;
}

std::vector<std::ptrdiff_t> costsOf(const std::vector<StencilBlocks>& bodies,
                                    const std::vector<Index>& cuts) {
    std::vector<std::ptrdiff_t> costs(cuts.size() - 1, 0);
    for (const StencilBlocks& body : bodies)
        for (std::size_t k = 0; k < body.blocks.size(); ++k) {
            const auto r =
                std::upper_bound(cuts.begin(), cuts.end(), body.blocks[k].begin) - cuts.begin() - 1;
            costs[static_cast<std::size_t>(r)] += body.cost[k + 1] - body.cost[k];
        }
    return costs;
}

std::vector<HaloPeer> planHalo(const Reference& ref, const std::vector<Index>& cuts, int process) {
    const auto me = static_cast<std::size_t>(process);
    const Index lo = cuts[me], hi = cuts[me + 1];
    const std::vector<Index> mine = readsOutside(ref, lo, hi);
    std::vector<HaloPeer> peers;
    for (std::size_t q = 0; q + 1 < cuts.size(); ++q) {
        if (q == me) continue;
        HaloPeer peer;
        peer.process = static_cast<int>(q);
        peer.receive = within(mine, cuts[q], cuts[q + 1]);
        peer.send = within(readsOutside(ref, cuts[q], cuts[q + 1]), lo, hi);
        if (!peer.send.empty() || !peer.receive.empty()) peers.push_back(std::move(peer));
    }
    return peers;
}

}  // namespace gsph
