// SPDX-License-Identifier: MIT
// The pairs of the CSR path staged as SoA weights, so that the pair loops of particles off the
// stencil blocks (overset spaces, the band, broken bonds) run in SIMD lanes
// (forces/internal_force.cpp, kinematics/deformation_gradient.hpp): across one particle's pairs
// (a run, StagedPairs) or across 8 consecutive particles (a masked strip, StripPairs).
//
// A particle's run holds its own list's pairs that hold (less those its masked strip takes),
// then the pairs across spaces whose transposed term comes from the other side's list
// (Reference::crossPair) and not from a pair of its own list, padded to a multiple of kPairLanes
// (core/lanes.hpp). A pair across spaces that both lists hold is one entry with both lists'
// terms, so b's fields are gathered once for it. Per pair, with
// w_cb = ω∇W_cb the table's weight and δw the interface corrections
// (overset/interface_weights.hpp), DESIGN §4 and §6:
//   wOwn  w_cb + c's correction (when c keeps all its bonds): F's sum and the stress sum Σ w_cb;
//         0 for a pair of the other side's list;
//   wT    the transposed stress term's weight: w_cb − the mirror's correction (same space,
//         when b keeps all its bonds), −(w_bc + b's correction) from b's list across spaces
//         (0 when b's list does not hold the pair);
//   gQ    the viscous sum's weight: w_cb (own list), 0 (b's list);
//   gN    the viscous transposed term's: w_cb same space, −w_bc from b's list across spaces
//         (0 when it does not hold the pair);
//   hBar ½(h_c + h_b) (the viscosity's);
//   hgWeight  ½(V_c + V_b) ω W (the hourglass pair's weight, forces/hourglass.hpp); for a pair
//         across spaces that both lists hold, W is the sum of their kernels' W (the force is
//         linear in it: the two halves' sum to round-off);
//   share the hourglass force's share (1 within a space, ½ across, the other half on the
//         other side), 0 for padding (b = c): the loops read share ≠ 0 as "the pair exists".
// hBar and hgWeight are reference data the force would otherwise gather per pair at every step;
// they are computed here with the same operations, so the bits do not change. The reference
// offset X_b − X_c is not stored: the force forms it from X in b's row
// (neighbors/pair_field_rows.hpp), which it loads anyway.
// Signs and zeros are exact, so a term that is absent adds exactly nothing (a sum that starts
// at +0 never becomes −0).
#pragma once

#include <cstddef>
#include <vector>

#include "core/lanes.hpp"
#include "core/soa_field.hpp"
#include "core/types.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/bond_view.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// The pairs of the CSR path staged as SoA weights (what the vectorised CSR loops read;
/// entry i of a vector weight's component r at [r * stride + i]): per pair that holds, the
/// neighbour b and the weights of each term, signed and zero where the term is absent; each
/// particle's run padded to a multiple of 8 with entries whose `share` is 0.
struct StagedPairs {
    std::vector<Index> b;
    std::vector<double> wOwn, wT, gQ, gN, hBar, hgWeight, share;
    std::size_t stride = 0;
    void resize(std::size_t n) {
        stride = cacheSpreadStride(n);  // the components of a vector weight in distinct sets
        b.resize(stride), hBar.resize(stride), hgWeight.resize(stride), share.resize(stride);
        wOwn.resize(3 * stride), wT.resize(3 * stride), gQ.resize(3 * stride);
        gN.resize(3 * stride);
    }
};

/// The weights of masked strips' entries (below), per entry and lane: wOwn and wT as in
/// StagedPairs, g = the table's w_cb (which gQ and gN both are for a same-space pair), W, and
/// valid (1: the lane has the pair; 0: zeros). The reference offset, h̄ and the hourglass
/// weight are not stored: the strip loads X, h and V of a + δ contiguously and forms them with
/// the operations a run's staging uses, so the bits are the same. 88 bytes an entry.
struct StripPairs {
    std::vector<double> wOwn, wT, g, W, valid;
    std::size_t stride = 0;
    void resize(std::size_t n) {
        stride = cacheSpreadStride(n);
        W.resize(stride), valid.resize(stride);
        wOwn.resize(3 * stride), wT.resize(3 * stride), g.resize(3 * stride);
    }
};

/// A masked strip: the CSR particles first … first + kPairLanes − 1 (consecutive, one block),
/// whose same-space pairs run as a stencil with per-lane weights: entry e has the offset
/// δ_e = b − a (the union of the lanes' offsets, ascending), lane i its pair (first + i,
/// first + i + δ_e) or zeros with valid 0 where that particle has no such pair. Entry e, lane i
/// is entry base + e kPairLanes + i of CsrPairWeights::stripPairs, so a lane's weights and its
/// neighbours' fields (at a + δ_e) are both contiguous loads.
struct MaskedStrip {
    Index first = 0;
    Index deltaBegin = 0, deltaEnd = 0;  ///< into CsrPairWeights::delta
    std::size_t base = 0;
};

/// Every CSR particle's pairs staged once in the reference configuration, all bonds intact: the
/// same-space pairs of the particles in masked strips (stripAt[a] ≥ 0 for a strip's first
/// particle) as strips; the rest of particle a's pairs (all of them outside strips) as its run
/// [begin[a], begin[a + 1]) of `pairs`, gathered. The force and θ-gradient loops read it for every
/// particle whose staged weights hold and stage the pairs of the others themselves
/// (stagedStrips, stageIntoScratch: the same pairs in one run; the same result to round-off).
struct CsrPairWeights {
    std::vector<std::size_t> begin;
    StagedPairs pairs;
    std::vector<Index> stripAt;  ///< per particle: its strip if it is one's first, else −1
    std::vector<MaskedStrip> strips;
    std::vector<Index> delta;
    StripPairs stripPairs;
    /// Per CSR particle: Σ wOwn over its strip's and its run's entries, added as the force's
    /// lanes add them (ownWeightSum), so that the force takes the stress term's Σ w of a particle
    /// whose staged weights hold from here instead of streaming wOwn again (the same bits).
    std::vector<Vec3> ownSum;
    /// The particles whose fields the runs of these blocks' CSR particles may read, ascending:
    /// each CSR particle (its padding's b), the neighbours of its own list and the owners of its
    /// pairs from other lists (all of them: a particle whose bonds changed stages every pair
    /// that holds into its run). Where the runs read them from rows
    /// (neighbors/pair_field_rows.hpp).
    std::vector<Index> gathered;
    std::size_t bytes() const;
};
CsrPairWeights stageCsrPairs(const Reference& ref, const StencilBlocks& blocks);

/// Σ wOwn over CSR particle c's staged entries, in the force's order: its masked strip's lane
/// (entries in order from +0), plus its run's kPairLanes lanes reduced by sumPairLanes.
Vec3 ownWeightSum(const CsrPairWeights& w, Index c);

/// Which of a CSR block's particles read `staged` and which stage their pairs afresh: afresh[i]
/// for column i when there is nothing staged, the block was not staged (a stencil block on the
/// CSR path for a broken bond), the particle's staged weights are stale (BondView::stale), or
/// it belongs to a masked strip with such a particle (a strip is read whole or not at all).
/// Calls strip(i, s) for every masked strip s read, i the column of its first particle.
template <class StripFn>
inline void stagedStrips(const CsrPairWeights* staged, const BondView& bonds,
                         const ParticleBlock& block, bool* afresh, StripFn&& strip) {
    const Index len = block.size();
    const bool none = staged == nullptr || block.stencil != kNoStencil;
    for (Index i = 0; i < len; ++i) afresh[i] = none || !bonds.keepsStaged(block.particle(i));
    if (none) return;
    for (Index i = 0; i < len; ++i) {
        const Index t = staged->stripAt[static_cast<std::size_t>(block.particle(i))];
        if (t < 0) continue;
        bool whole = true;
        for (Index u = i; u < i + kPairLanes; ++u) whole = whole && !afresh[u];
        if (whole)
            strip(i, staged->strips[static_cast<std::size_t>(t)]);
        else
            for (Index u = i; u < i + kPairLanes; ++u) afresh[u] = true;
    }
}

/// Stages all of particle c's pairs that `bonds` keeps, in one run from entry 0, into this
/// thread's buffer (grown as needed, never shrunk: no allocation once it has grown); returns
/// the buffer, valid until the thread's next call, and the count (padded to kPairLanes) in size.
const StagedPairs& stageIntoScratch(const Reference& ref, const BondView& bonds, Index c,
                                    Index& size);

}  // namespace gsph
