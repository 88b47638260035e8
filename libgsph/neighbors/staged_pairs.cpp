// SPDX-License-Identifier: MIT
#include "neighbors/staged_pairs.hpp"

#include "core/parallel.hpp"

namespace gsph {

Index stagedCount(const Reference& ref, const BondView& bonds, Index c) {
    const PairList& P = ref.pairs;
    const auto ic = static_cast<std::size_t>(c);
    Index n = 0;
    for (Index k = P.begin(c); k < P.end(c); ++k) n += bonds.holds(k) ? 1 : 0;
    if (!ref.crossOffset.empty())
        for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot)
            n += bonds.holds(ref.crossPair[static_cast<std::size_t>(slot)]) ? 1 : 0;
    return (n + kPairLanes - 1) / kPairLanes * kPairLanes;
}

Index stagedCapacity(const Reference& ref, Index c) {
    const auto ic = static_cast<std::size_t>(c);
    const Index cross = ref.crossOffset.empty() ? 0 : ref.crossOffset[ic + 1] - ref.crossOffset[ic];
    return ref.pairs.end(c) - ref.pairs.begin(c) + cross + kPairLanes;
}

Index stagePairs(const Reference& ref, const BondView& bonds, Index c, StagedPairs& st,
                 std::size_t begin) {
    const PairList& P = ref.pairs;
    const KernelEntry* table = P.table.data();
    const auto ic = static_cast<std::size_t>(c);
    const std::size_t m = st.stride;
    std::size_t i = begin;
    const auto put = [&](Index b, const Vec3& own, const Vec3& wT, const Vec3& gQ, const Vec3& gN,
                         double W, double share, double valid) {
        const auto ib = static_cast<std::size_t>(b);
        const Vec3 Y = ref.X[ib] - ref.X[ic];
        st.b[i] = b, st.share[i] = share, st.valid[i] = valid;
        st.Y2[i] = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
        st.hBar[i] = 0.5 * (ref.smoothingLength[ic] + ref.smoothingLength[ib]);
        st.hgWeight[i] = 0.5 * (ref.quadVolume[ic] + ref.quadVolume[ib]) * W;
        for (std::size_t r = 0; r < 3; ++r) {
            const auto e = static_cast<Eigen::Index>(r);
            st.wOwn[r * m + i] = own[e], st.wT[r * m + i] = wT[e];
            st.gQ[r * m + i] = gQ[e], st.gN[r * m + i] = gN[e], st.Y[r * m + i] = Y[e];
        }
        ++i;
    };
    const Vec3* own = bonds.keepsAll(c) ? ref.pairCorrections(c) : nullptr;
    const Vec3* mirror = ref.mirrorCorrections(c);
    const Vec3 zero = Vec3::Zero();
    for (Index k = P.begin(c); k < P.end(c); ++k) {
        if (!bonds.holds(k)) continue;
        const Index b = P.neighbor[static_cast<std::size_t>(k)];
        const KernelEntry& e = table[P.kernelId[static_cast<std::size_t>(k)]];
        const auto slot = static_cast<std::size_t>(k - P.begin(c));
        const Vec3 w = own != nullptr ? Vec3(e.gradW + own[slot]) : e.gradW;
        if (ref.space[static_cast<std::size_t>(b)] != ref.space[ic]) {
            put(b, w, zero, e.gradW, zero, e.W, 0.5, 1.0);
        } else {
            // −K_b w_bc with w_bc = −w_cb + (the mirror's correction)
            const Vec3 wT =
                mirror != nullptr && bonds.keepsAll(b) ? Vec3(e.gradW - mirror[slot]) : e.gradW;
            put(b, w, wT, e.gradW, e.gradW, e.W, 1.0, 1.0);
        }
    }
    if (!ref.crossOffset.empty())
        for (Index slot = ref.crossOffset[ic]; slot < ref.crossOffset[ic + 1]; ++slot) {
            const Index k = ref.crossPair[static_cast<std::size_t>(slot)];
            if (!bonds.holds(k)) continue;
            const Index owner = ref.crossOwner[static_cast<std::size_t>(slot)];
            const KernelEntry& e = table[P.kernelId[static_cast<std::size_t>(k)]];  // w_bc
            const Vec3* ownerCorrection =
                bonds.keepsAll(owner) ? ref.pairCorrections(owner) : nullptr;
            const Vec3 w = ownerCorrection != nullptr
                               ? Vec3(e.gradW + ownerCorrection[k - P.begin(owner)])
                               : e.gradW;
            put(owner, zero, -w, zero, -e.gradW, e.W, 0.5, 1.0);
        }
    const std::size_t padded =
        begin + static_cast<std::size_t>((i - begin + kPairLanes - 1) / kPairLanes * kPairLanes);
    while (i < padded) put(c, zero, zero, zero, zero, 0.0, 0.0, 0.0);
    return static_cast<Index>(padded - begin);
}

std::size_t CsrPairWeights::bytes() const {
    return begin.size() * sizeof(std::size_t) +
           pairs.stride * (sizeof(Index) + 13 * sizeof(double));
}

CsrPairWeights stageCsrPairs(const Reference& ref, const StencilBlocks& blocks) {
    CsrPairWeights out;
    const auto n = static_cast<std::size_t>(ref.size());
    std::vector<Index> count(n, 0);
    for (const ParticleBlock& block : blocks.blocks)
        if (block.stencil == kNoStencil)
            for (Index i = 0; i < block.size(); ++i)
                count[static_cast<std::size_t>(block.particle(i))] =
                    stagedCount(ref, BondView{}, block.particle(i));
    out.begin.assign(n + 1, 0);
    for (std::size_t a = 0; a < n; ++a)
        out.begin[a + 1] = out.begin[a] + static_cast<std::size_t>(count[a]);
    out.pairs.resize(out.begin[n]);
    parallelFor(ref.size(), [&](Index a) {
        if (count[static_cast<std::size_t>(a)] > 0)
            stagePairs(ref, BondView{}, a, out.pairs, out.begin[static_cast<std::size_t>(a)]);
    });
    return out;
}

}  // namespace gsph
