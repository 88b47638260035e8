// SPDX-License-Identifier: MIT
#include "neighbors/stencil_blocks.hpp"

#include <algorithm>
#include <map>

namespace gsph {
namespace {

// The neighbour list of a, relative to a: entries (b − a) then kernel ids.
std::vector<Index> relativeList(const PairList& P, Index a) {
    std::vector<Index> key;
    key.reserve(2 * static_cast<std::size_t>(P.end(a) - P.begin(a)));
    for (Index k = P.begin(a); k < P.end(a); ++k)
        key.push_back(P.neighbor[static_cast<std::size_t>(k)] - a);
    for (Index k = P.begin(a); k < P.end(a); ++k)
        key.push_back(P.kernelId[static_cast<std::size_t>(k)]);
    return key;
}

// True when b's list is a's list shifted by b − a (same length, deltas and kernel entries).
bool sameStencil(const PairList& P, Index a, Index b) {
    const Index n = P.end(a) - P.begin(a);
    if (n == 0 || P.end(b) - P.begin(b) != n) return false;
    for (Index k = 0; k < n; ++k) {
        const auto ka = static_cast<std::size_t>(P.begin(a) + k);
        const auto kb = static_cast<std::size_t>(P.begin(b) + k);
        if (P.neighbor[ka] - a != P.neighbor[kb] - b || P.kernelId[ka] != P.kernelId[kb])
            return false;
    }
    return true;
}

// Splits the run of `count` particles first, first + stride, ... into ⌈count/kMaxBlock⌉ blocks
// of near-equal length, so that a stencil run never leaves a remainder shorter than
// kMinStencilRun (the strips need ≥ 4 particles).
void appendBlocks(std::vector<ParticleBlock>& blocks, Index first, Index count, Index stride,
                  Index stencil) {
    if (count <= 0) return;
    const Index parts = (count + kMaxBlock - 1) / kMaxBlock;
    for (Index i = 0; i < parts; ++i) {
        const Index p0 = count * i / parts, p1 = count * (i + 1) / parts;
        blocks.push_back({first + p0 * stride, first + (p1 - 1) * stride + 1, stencil, stride});
    }
}

Stencil makeStencil(const PairList& P, Index a) {
    Stencil s;
    for (Index k = P.begin(a); k < P.end(a); ++k) {
        const auto ik = static_cast<std::size_t>(k);
        s.delta.push_back(P.neighbor[ik] - a);
        s.kernelId.push_back(P.kernelId[ik]);
        const KernelEntry& e = P.table[static_cast<std::size_t>(P.kernelId[ik])];
        s.gradW.push_back(e.gradW);
        s.W.push_back(e.W);
        s.sumGradW += e.gradW;
    }
    const std::size_t m = s.delta.size();
    s.symmetric = m % 2 == 0;
    for (std::size_t k = 0; k < m && s.symmetric; ++k)
        s.symmetric = s.delta[m - 1 - k] == -s.delta[k] && s.gradW[m - 1 - k] == -s.gradW[k] &&
                      s.W[m - 1 - k] == s.W[k];
    if (s.symmetric) s.sumGradW.setZero();  // mirrored pairs cancel exactly
    return s;
}

}  // namespace

std::size_t StencilBlocks::bytes() const {
    std::size_t b = blocks.capacity() * sizeof(ParticleBlock);
    for (const Stencil& s : stencils)
        b += sizeof(Stencil) + (s.delta.capacity() + s.kernelId.capacity()) * sizeof(Index) +
             s.gradW.capacity() * sizeof(Vec3) + s.W.capacity() * sizeof(double);
    return b;
}

StencilBlocks buildStencilBlocks(const PairList& pairs, Index begin, Index end,
                                 const std::vector<std::uint8_t>& csrOnly) {
    const auto stencilAllowed = [&](Index a) {
        return csrOnly.empty() || csrOnly[static_cast<std::size_t>(a)] == 0;
    };
    StencilBlocks out;
    out.particles = std::max<Index>(end - begin, 0);
    std::map<std::vector<Index>, Index> known;  // relative list → stencil id
    const auto stencilOf = [&](Index a) {
        const auto [it, inserted] =
            known.try_emplace(relativeList(pairs, a), static_cast<Index>(out.stencils.size()));
        if (inserted) out.stencils.push_back(makeStencil(pairs, a));
        return it->second;
    };
    std::vector<std::uint8_t> taken(static_cast<std::size_t>(out.particles), 0);
    const auto free = [&](Index a) {
        return a < end && taken[static_cast<std::size_t>(a - begin)] == 0 && stencilAllowed(a);
    };
    const auto take = [&](Index first, Index count, Index stride) {
        for (Index m = 0; m < count; ++m)
            taken[static_cast<std::size_t>(first + m * stride - begin)] = 1;
        appendBlocks(out.blocks, first, count, stride, stencilOf(first));
    };
    // A particle beside one that must take the CSR path (a ± 1) joins no run across rows: it
    // would cut the CSR particles' rows into pieces shorter than a masked strip's 8 lanes
    // (neighbors/staged_pairs.hpp), whose pairs then go to gathered runs, dearer per pair than
    // the strided block saves (an O-grid's annulus whose outer ring alone is off the band).
    const auto besideCsrOnly = [&](Index a) {
        return (a > begin && !stencilAllowed(a - 1)) || (a + 1 < end && !stencilAllowed(a + 1));
    };
    const auto freeAcross = [&](Index a) { return free(a) && !besideCsrOnly(a); };
    // Runs of consecutive particles first, then runs across rows among the rest: the strides
    // tried are a's own positive neighbour offsets, shortest first.
    for (Index a = begin; a < end;) {
        Index runEnd = a + 1;
        if (free(a))
            while (free(runEnd) && sameStencil(pairs, a, runEnd)) ++runEnd;
        if (free(a) && runEnd - a >= kMinStencilRun) take(a, runEnd - a, 1);
        a = runEnd;
    }
    for (Index a = begin; a < end; ++a) {
        if (!freeAcross(a)) continue;
        for (Index k = pairs.begin(a); k < pairs.end(a); ++k) {
            const Index stride = pairs.neighbor[static_cast<std::size_t>(k)] - a;
            if (stride <= 1) continue;
            Index count = 1;
            while (freeAcross(a + count * stride) && sameStencil(pairs, a, a + count * stride))
                ++count;
            if (count >= kMinStencilRun) {
                take(a, count, stride);
                break;
            }
        }
    }
    // The rest: CSR blocks of consecutive particles.
    for (Index a = begin; a < end;) {
        if (taken[static_cast<std::size_t>(a - begin)] != 0) {
            ++a;
            continue;
        }
        Index runEnd = a + 1;
        while (runEnd < end && taken[static_cast<std::size_t>(runEnd - begin)] == 0) ++runEnd;
        appendBlocks(out.blocks, a, runEnd - a, 1, kNoStencil);
        a = runEnd;
    }
    std::sort(out.blocks.begin(), out.blocks.end(),
              [](const ParticleBlock& x, const ParticleBlock& y) { return x.begin < y.begin; });
    out.cost.assign(1, 0);
    for (const ParticleBlock& block : out.blocks)
        out.cost.push_back(out.cost.back() + block.cost());
    return out;
}

}  // namespace gsph
