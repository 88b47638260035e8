// SPDX-License-Identifier: MIT
#include "neighbors/staged_pairs.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace gsph {

namespace {

// One staged pair: its neighbour and the weights of its terms (staged_pairs.hpp).
struct PairRecord {
    Index b = 0;
    Vec3 own = Vec3::Zero(), wT = Vec3::Zero(), gQ = Vec3::Zero(), gN = Vec3::Zero();
    double W = 0.0, share = 0.0;
};

// Pair k of c's own list (it holds).
PairRecord ownRecord(const Reference& ref, const BondView& bonds, Index c, Index k) {
    const PairList& P = ref.pairs;
    const auto ic = static_cast<std::size_t>(c);
    const Vec3* own = bonds.keepsAll(c) ? ref.pairCorrections(c) : nullptr;
    const Vec3* mirror = ref.mirrorCorrections(c);
    PairRecord r;
    r.b = P.neighbor[static_cast<std::size_t>(k)];
    const KernelEntry& e = P.table[P.kernelId[static_cast<std::size_t>(k)]];
    const auto slot = static_cast<std::size_t>(k - P.begin(c));
    r.own = own != nullptr ? Vec3(e.gradW + own[slot]) : e.gradW;
    r.gQ = e.gradW;
    r.W = e.W;
    if (ref.space[static_cast<std::size_t>(r.b)] != ref.space[ic]) {
        r.share = 0.5;
    } else {
        // −K_b w_bc with w_bc = −w_cb + (the mirror's correction)
        r.wT = mirror != nullptr && bonds.keepsAll(r.b) ? Vec3(e.gradW - mirror[slot]) : e.gradW;
        r.gN = e.gradW;
        r.share = 1.0;
    }
    return r;
}

// The pair k = (owner, c) of the other side's list, across spaces (it holds).
PairRecord crossRecord(const Reference& ref, const BondView& bonds, Index k, Index owner) {
    const PairList& P = ref.pairs;
    const KernelEntry& e = P.table[P.kernelId[static_cast<std::size_t>(k)]];  // w_bc
    const Vec3* ownerCorrection = bonds.keepsAll(owner) ? ref.pairCorrections(owner) : nullptr;
    const Vec3 w =
        ownerCorrection != nullptr ? Vec3(e.gradW + ownerCorrection[k - P.begin(owner)]) : e.gradW;
    PairRecord r;
    r.b = owner;
    r.wT = -w;
    r.gN = -e.gradW;
    r.W = e.W;
    r.share = 0.5;
    return r;
}

// Writes r as entry i of st for centre c.
void put(const Reference& ref, Index c, const PairRecord& r, StagedPairs& st, std::size_t i) {
    const auto ic = static_cast<std::size_t>(c), ib = static_cast<std::size_t>(r.b);
    const std::size_t m = st.stride;
    st.b[i] = r.b, st.share[i] = r.share;
    st.hBar[i] = 0.5 * (ref.smoothingLength[ic] + ref.smoothingLength[ib]);
    st.hgWeight[i] = 0.5 * (ref.quadVolume[ic] + ref.quadVolume[ib]) * r.W;
    for (std::size_t q = 0; q < 3; ++q) {
        const auto e = static_cast<Eigen::Index>(q);
        st.wOwn[q * m + i] = r.own[e], st.wT[q * m + i] = r.wT[e];
        st.gQ[q * m + i] = r.gQ[e], st.gN[q * m + i] = r.gN[e];
    }
}

// The slot of c's pairs from the other side's lists (Reference::crossOffset) whose owner is b
// and that holds, or −1.
Index heldCrossSlot(const Reference& ref, const BondView& bonds, Index c, Index b) {
    const auto ic = static_cast<std::size_t>(c);
    for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot)
        if (ref.crossOwner[static_cast<std::size_t>(slot)] == b &&
            bonds.holds(ref.crossPair[static_cast<std::size_t>(slot)]))
            return slot;
    return -1;
}

// Whether c's own list holds a pair with b.
bool holdsOwnPair(const Reference& ref, const BondView& bonds, Index c, Index b) {
    const PairList& P = ref.pairs;
    for (Index k = P.begin(c); k < P.end(c); ++k)
        if (P.neighbor[static_cast<std::size_t>(k)] == b && bonds.holds(k)) return true;
    return false;
}

// Calls visit(record) for every pair of c that holds and is not `taken` (per own-list pair;
// null: none), own list first. A pair across spaces that both lists hold, (c, b) in c's and
// (b, c) in b's, is one record: it reads b's fields once. Its terms are the two records'
// (the own one has no transposed or viscous-transposed weight, the other no own or viscous
// one), and its hourglass weight the sum of both kernels' W at the same share ½, the same
// force to round-off (forces/hourglass.hpp is linear in the weight).
template <class Visit>
void forEachPair(const Reference& ref, const BondView& bonds, Index c, const std::uint8_t* taken,
                 Visit&& visit) {
    const PairList& P = ref.pairs;
    const auto ic = static_cast<std::size_t>(c);
    const bool overset = !ref.crossOffset.empty();
    for (Index k = P.begin(c); k < P.end(c); ++k) {
        if (!bonds.holds(k) || (taken != nullptr && taken[k] != 0)) continue;
        PairRecord r = ownRecord(ref, bonds, c, k);
        if (overset && ref.space[static_cast<std::size_t>(r.b)] != ref.space[ic]) {
            const Index slot = heldCrossSlot(ref, bonds, c, r.b);
            if (slot >= 0) {
                const PairRecord t =
                    crossRecord(ref, bonds, ref.crossPair[static_cast<std::size_t>(slot)], r.b);
                r.wT = t.wT, r.gN = t.gN, r.W += t.W;
            }
        }
        visit(r);
    }
    if (overset)
        for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot) {
            const Index k = ref.crossPair[static_cast<std::size_t>(slot)];
            const Index owner = ref.crossOwner[static_cast<std::size_t>(slot)];
            if (bonds.holds(k) && !holdsOwnPair(ref, bonds, c, owner))
                visit(crossRecord(ref, bonds, k, owner));
        }
}

Index padded(Index n) {
    return (n + kPairLanes - 1) / kPairLanes * kPairLanes;
}

Index restCount(const Reference& ref, const BondView& bonds, Index c, const std::uint8_t* taken) {
    Index n = 0;
    forEachPair(ref, bonds, c, taken, [&](const PairRecord&) { ++n; });
    return padded(n);
}

Index stageRest(const Reference& ref, const BondView& bonds, Index c, const std::uint8_t* taken,
                StagedPairs& st, std::size_t begin) {
    std::size_t i = begin;
    forEachPair(ref, bonds, c, taken, [&](const PairRecord& r) { put(ref, c, r, st, i++); });
    const std::size_t end = begin + static_cast<std::size_t>(padded(static_cast<Index>(i - begin)));
    PairRecord none;
    none.b = c;
    for (; i < end; ++i) put(ref, c, none, st, i);
    return static_cast<Index>(end - begin);
}

}  // namespace

const StagedPairs& stageIntoScratch(const Reference& ref, const BondView& bonds, Index c,
                                    Index& size) {
    thread_local StagedPairs scratch;
    const auto ic = static_cast<std::size_t>(c);
    const Index cross = ref.crossOffset.empty() ? 0 : ref.crossOffset[ic + 1] - ref.crossOffset[ic];
    const auto need =
        static_cast<std::size_t>(ref.pairs.end(c) - ref.pairs.begin(c) + cross + kPairLanes);
    if (scratch.stride < need) scratch.resize(std::max(need, 2 * scratch.stride));
    size = stageRest(ref, bonds, c, nullptr, scratch, 0);
    return scratch;
}

std::size_t CsrPairWeights::bytes() const {
    return begin.size() * sizeof(std::size_t) + stripAt.size() * sizeof(Index) +
           strips.size() * sizeof(MaskedStrip) + delta.size() * sizeof(Index) +
           gathered.size() * sizeof(Index) + pairs.stride * (sizeof(Index) + 15 * sizeof(double)) +
           stripPairs.stride * 11 * sizeof(double) + ownSum.size() * sizeof(Vec3);
}

CsrPairWeights stageCsrPairs(const Reference& ref, const StencilBlocks& blocks) {
    CsrPairWeights out;
    const PairList& P = ref.pairs;
    const Index n = ref.size();
    const auto un = static_cast<std::size_t>(n);
    out.stripAt.assign(un, -1);
    // Masked strips: 8 consecutive CSR particles of one block; an entry per offset δ that a
    // lane's same-space pair has, if every lane's a + δ is a particle (the loads stay inside).
    std::vector<std::uint8_t> taken(static_cast<std::size_t>(P.pairs()), 0);
    std::size_t entries = 0;
    for (const ParticleBlock& block : blocks.blocks) {
        if (block.stencil != kNoStencil || block.stride != 1) continue;
        for (Index c0 = block.begin; c0 + kPairLanes <= block.end; c0 += kPairLanes) {
            std::vector<Index> deltas;
            for (Index c = c0; c < c0 + kPairLanes; ++c)
                for (Index k = P.begin(c); k < P.end(c); ++k) {
                    const Index b = P.neighbor[static_cast<std::size_t>(k)];
                    const Index d = b - c;
                    if (ref.space[static_cast<std::size_t>(b)] !=
                            ref.space[static_cast<std::size_t>(c)] ||
                        c0 + d < 0 || c0 + kPairLanes - 1 + d >= n)
                        continue;
                    taken[static_cast<std::size_t>(k)] = 1;
                    deltas.push_back(d);
                }
            if (deltas.empty()) continue;
            std::sort(deltas.begin(), deltas.end());
            deltas.erase(std::unique(deltas.begin(), deltas.end()), deltas.end());
            MaskedStrip strip;
            strip.first = c0;
            strip.deltaBegin = static_cast<Index>(out.delta.size());
            strip.deltaEnd = strip.deltaBegin + static_cast<Index>(deltas.size());
            strip.base = entries;
            entries += deltas.size() * kPairLanes;
            out.delta.insert(out.delta.end(), deltas.begin(), deltas.end());
            out.stripAt[static_cast<std::size_t>(c0)] = static_cast<Index>(out.strips.size());
            out.strips.push_back(strip);
        }
    }
    // The rest of each CSR particle's pairs, gathered.
    std::vector<Index> count(un, 0);
    for (const ParticleBlock& block : blocks.blocks)
        if (block.stencil == kNoStencil)
            for (Index i = 0; i < block.size(); ++i) {
                const Index c = block.particle(i);
                count[static_cast<std::size_t>(c)] = restCount(ref, BondView{}, c, taken.data());
            }
    out.begin.assign(un + 1, 0);
    for (std::size_t a = 0; a < un; ++a)
        out.begin[a + 1] = out.begin[a] + static_cast<std::size_t>(count[a]);
    out.pairs.resize(out.begin[un]);
    parallelFor(n, [&](Index a) {
        if (count[static_cast<std::size_t>(a)] > 0)
            stageRest(ref, BondView{}, a, taken.data(), out.pairs,
                      out.begin[static_cast<std::size_t>(a)]);
    });
    std::vector<std::uint8_t> read(un, 0);
    for (const ParticleBlock& block : blocks.blocks)
        if (block.stencil == kNoStencil)
            for (Index i = 0; i < block.size(); ++i) {
                const Index c = block.particle(i);
                const auto ic = static_cast<std::size_t>(c);
                read[ic] = 1;
                for (Index k = P.begin(c); k < P.end(c); ++k)
                    read[static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)])] = 1;
                if (!ref.crossOffset.empty())
                    for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot)
                        read[static_cast<std::size_t>(
                            ref.crossOwner[static_cast<std::size_t>(slot)])] = 1;
            }
    for (Index a = 0; a < n; ++a)
        if (read[static_cast<std::size_t>(a)] != 0) out.gathered.push_back(a);
    out.stripPairs.resize(entries);  // zeros: no pair
    parallelFor(static_cast<Index>(out.strips.size()), [&](Index t) {
        const MaskedStrip& strip = out.strips[static_cast<std::size_t>(t)];
        const Index* d0 = out.delta.data() + strip.deltaBegin;
        const Index* d1 = out.delta.data() + strip.deltaEnd;
        StripPairs& sp = out.stripPairs;
        const std::size_t m = sp.stride;
        for (Index i = 0; i < kPairLanes; ++i) {
            const Index c = strip.first + i;
            for (Index k = P.begin(c); k < P.end(c); ++k) {
                if (taken[static_cast<std::size_t>(k)] == 0) continue;
                const Index d = P.neighbor[static_cast<std::size_t>(k)] - c;
                const auto e = static_cast<Index>(std::lower_bound(d0, d1, d) - d0);
                const std::size_t j = strip.base + static_cast<std::size_t>(e * kPairLanes + i);
                const PairRecord r = ownRecord(ref, BondView{}, c, k);
                sp.W[j] = r.W, sp.valid[j] = 1.0;
                for (std::size_t q = 0; q < 3; ++q) {
                    const auto qe = static_cast<Eigen::Index>(q);
                    sp.wOwn[q * m + j] = r.own[qe], sp.wT[q * m + j] = r.wT[qe];
                    sp.g[q * m + j] = r.gQ[qe];
                }
            }
        }
    });
    out.ownSum.assign(un, Vec3::Zero());
    parallelFor(n,
                [&](Index c) { out.ownSum[static_cast<std::size_t>(c)] = ownWeightSum(out, c); });
    return out;
}

Vec3 ownWeightSum(const CsrPairWeights& w, Index c) {
    const auto ic = static_cast<std::size_t>(c);
    Vec3 sum = Vec3::Zero();
    // A masked strip's lane sums its entries in order from +0 (internal_force.cpp); c is lane
    // i of the strip that starts at c − i, if any.
    for (Index i = 0; i < kPairLanes && c - i >= 0; ++i) {
        const Index t = w.stripAt[static_cast<std::size_t>(c - i)];
        if (t < 0) continue;
        const MaskedStrip& strip = w.strips[static_cast<std::size_t>(t)];
        const StripPairs& sp = w.stripPairs;
        for (Index e = 0; e < strip.deltaEnd - strip.deltaBegin; ++e) {
            const std::size_t j = strip.base + static_cast<std::size_t>(e * kPairLanes + i);
            for (std::size_t q = 0; q < 3; ++q)
                sum[static_cast<Eigen::Index>(q)] += sp.wOwn[q * sp.stride + j];
        }
        break;
    }
    // A run's pairs go to kPairLanes lanes (pair j to lane j mod kPairLanes), reduced in the
    // fixed order of sumPairLanes and added to the strip's sum.
    const StagedPairs& st = w.pairs;
    for (std::size_t q = 0; q < 3; ++q) {
        Lanes2 lane[kPairLanes / kLanesOf<Lanes2>] = {};
        for (std::size_t j = w.begin[ic]; j < w.begin[ic + 1]; ++j) {
            const std::size_t l = (j - w.begin[ic]) % kPairLanes;
            lane[l / 2][l % 2] += st.wOwn[q * st.stride + j];
        }
        sum[static_cast<Eigen::Index>(q)] += sumPairLanes<Lanes2>(lane);
    }
    return sum;
}

}  // namespace gsph
