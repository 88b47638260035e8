// SPDX-License-Identifier: MIT
#include "distributed/halo_plan.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace gsph {
namespace {

// The particles outside [lo, hi) that the particles of [lo, hi) read, ascending.
std::vector<Index> readsOutside(const Reads& reads, Index lo, Index hi) {
    std::vector<Index> read, out;
    for (Index a = lo; a < hi; ++a) {
        read.clear();
        reads(a, read);
        for (Index b : read)
            if (b < lo || b >= hi) out.push_back(b);
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
                             int processes, bool cutStrided) {
    if (processes < 1) throw InputError("a run needs at least one process");
    const auto n = static_cast<std::size_t>(particles);
    // costBefore[c]: the cost of the particles below c; forbidden[c] > 0 where a cut at c would
    // split a block of consecutive particles, or leave a strided block a part shorter than a
    // strip (kMinStencilRun): a difference array over c.
    std::vector<std::ptrdiff_t> costBefore(n + 1, 0);
    std::vector<int> forbidden(n + 2, 0);
    const auto forbid = [&](Index from, Index to) {  // the cuts c in [from, to]
        if (from > to) return;
        ++forbidden[static_cast<std::size_t>(from)];
        --forbidden[static_cast<std::size_t>(to) + 1];
    };
    for (const StencilBlocks& body : bodies)
        for (const ParticleBlock& block : body.blocks) {
            for (Index i = 0; i < block.size(); ++i)
                costBefore[static_cast<std::size_t>(block.particle(i)) + 1] = block.particleCost();
            const Index m = block.size();
            if (block.stride == 1 || !cutStrided || m < 2 * kMinStencilRun) {
                forbid(block.begin + 1, block.particle(m - 1));
            } else {
                forbid(block.begin + 1, block.particle(kMinStencilRun - 1));
                forbid(block.particle(m - kMinStencilRun) + 1, block.particle(m - 1));
            }
        }
    for (std::size_t c = 1; c <= n; ++c) {
        costBefore[c] += costBefore[c - 1];
        forbidden[c] += forbidden[c - 1];
    }
    // Two cuts in one strided block: the part between them must be empty or a strip long too.
    std::vector<ParticleBlock> strided;
    for (const StencilBlocks& body : bodies)
        for (const ParticleBlock& block : body.blocks)
            if (block.stride > 1) strided.push_back(block);
    const auto leavesAStub = [&](Index previous, Index c) {
        for (const ParticleBlock& block : strided) {
            const Index part = block.within(previous, c).size();
            if (block.begin < previous && c < block.end && part > 0 && part < kMinStencilRun)
                return true;
        }
        return false;
    };
    const std::ptrdiff_t total = costBefore[n];
    std::vector<Index> cuts(static_cast<std::size_t>(processes) + 1, 0);
    cuts.back() = particles;
    std::size_t c = 1;
    for (int r = 1; r < processes; ++r) {
        const std::ptrdiff_t target = total * r / processes;
        const Index previous = cuts[static_cast<std::size_t>(r) - 1];
        while (c < n && (costBefore[c] < target || forbidden[c] > 0 ||
                         leavesAStub(previous, static_cast<Index>(c))))
            ++c;
        if (c >= n)
            throw InputError(std::to_string(processes) + " processes for " +
                             std::to_string(particles) +
                             " particles: the blocks leave some process none; run on fewer");
        cuts[static_cast<std::size_t>(r)] = static_cast<Index>(c++);
    }
    return cuts;
}

std::vector<std::ptrdiff_t> costsOf(const std::vector<StencilBlocks>& bodies,
                                    const std::vector<Index>& cuts) {
    std::vector<std::ptrdiff_t> costs(cuts.size() - 1, 0);
    for (const StencilBlocks& body : bodies)
        for (const ParticleBlock& block : body.blocks)
            for (std::size_t r = 0; r + 1 < cuts.size(); ++r)
                costs[r] += block.within(cuts[r], cuts[r + 1]).cost();
    return costs;
}

Reads pairReads(const Reference& ref) {
    return [&ref](Index a, std::vector<Index>& out) {
        const PairList& P = ref.pairs;
        for (Index k = P.begin(a); k < P.end(a); ++k)
            out.push_back(P.neighbor[static_cast<std::size_t>(k)]);
        if (!ref.crossOffset.empty())
            for (Index k = ref.crossOffset[static_cast<std::size_t>(a)];
                 k < ref.crossOffset[static_cast<std::size_t>(a) + 1]; ++k)
                out.push_back(ref.crossOwner[static_cast<std::size_t>(k)]);
    };
}

std::vector<HaloPeer> planHalo(const Reads& reads, const std::vector<Index>& cuts, int process) {
    const auto me = static_cast<std::size_t>(process);
    const Index lo = cuts[me], hi = cuts[me + 1];
    const std::vector<Index> mine = readsOutside(reads, lo, hi);
    std::vector<HaloPeer> peers;
    for (std::size_t q = 0; q + 1 < cuts.size(); ++q) {
        if (q == me) continue;
        HaloPeer peer;
        peer.process = static_cast<int>(q);
        peer.receive = within(mine, cuts[q], cuts[q + 1]);
        peer.send = within(readsOutside(reads, cuts[q], cuts[q + 1]), lo, hi);
        if (!peer.send.empty() || !peer.receive.empty()) peers.push_back(std::move(peer));
    }
    return peers;
}

}  // namespace gsph
