// SPDX-License-Identifier: MIT
// Blocks of consecutive particles that share one neighbour stencil (DESIGN §3).
//
// On a θ-lattice, the interior particles of a space (and the particles of one face or edge
// row) have the same neighbour list up to a shift by their own index: b = a + delta_k with the
// same kernel table entry for every k. Such a run of particles is one block with one Stencil,
// and the pair loops can run stencil entry by stencil entry across the whole block, reading
// each neighbour field contiguously (vectorisable across particles with SoA data). Everything
// else (lattice corners, periodic seams, overset and off-lattice pairs) is a block without
// stencil that takes the general CSR path. The partition is read off the PairList itself, so
// it holds for any pair list and never assumes a lattice.
//
// The lattice's faces normal to the fastest index (its "corner columns": a run along that index
// is at most two particles long there) share a stencil along the next index instead: particles
// a, a + s, a + 2s, ... with s the row length. Such a block has stride s; its strips gather the
// fields (core/lanes.hpp) and still run far faster than the CSR path. A particle beside one
// that must take the CSR path joins no such block: the CSR particles' rows stay whole, long
// enough for the CSR path's masked strips (neighbors/staged_pairs.hpp).
//
// Invariants: every particle of [begin, end) is in exactly one block, at most kMaxBlock
// particles each, blocks sorted by their first particle; for a stencil block and every a in it,
// the CSR list of a is exactly {(a + delta[k], kernelId[k])} in the same order. Built once per
// body; read-only afterwards.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "particles/pair_list.hpp"

namespace gsph {

/// Particles per block: the stencil kernels keep per-particle accumulators of one block on the
/// stack (18 doubles per particle in the kinematics), which must stay in L1.
inline constexpr Index kMaxBlock = 64;

/// Shortest run that becomes a stencil block; shorter runs take the CSR path (they gain no
/// vectorisation and would only multiply stencils).
inline constexpr Index kMinStencilRun = 4;

struct Stencil {
    std::vector<Index> delta;      ///< b − a per entry, ascending (the CSR order)
    std::vector<Index> kernelId;   ///< into PairList::table, per entry
    std::vector<Vec3> gradW;       ///< table[kernelId[k]].gradW, packed for the hot loops
    std::vector<double> W;         ///< table[kernelId[k]].W
    Vec3 sumGradW = Vec3::Zero();  ///< Σ_k gradW[k], in entry order; exactly 0 if symmetric
    /// Entry size()−1−k is entry k mirrored: delta and gradW negated exactly (the full
    /// interior stencil). Then Σ_k w_k = 0 exactly and Σ_k f_{a+δk} ⊗ w_k can be summed over
    /// the mirrored pairs as Σ_{k ≥ size()/2} (f_{a+δk} − f_{a−δk}) ⊗ w_k: half the work.
    bool symmetric = false;
    Index size() const { return static_cast<Index>(delta.size()); }
};

inline constexpr Index kNoStencil = -1;

/// The particles begin, begin + stride, ... below end.
struct ParticleBlock {
    Index begin = 0, end = 0;
    Index stencil = kNoStencil;  ///< into StencilBlocks::stencils, or kNoStencil (CSR path)
    Index stride = 1;            ///< 1, or > 1 for a stencil block across rows (see above)
    Index size() const { return (end - begin + stride - 1) / stride; }
    Index particle(Index i) const { return begin + i * stride; }
    /// One particle's share of StencilBlocks::cost: a CSR particle costs 4 stencil ones (see
    /// there); the block's share.
    std::ptrdiff_t particleCost() const { return stencil == kNoStencil ? 4 : 1; }
    std::ptrdiff_t cost() const { return size() * particleCost(); }
    /// The block's particles in [lo, hi), with its stencil and stride (size 0 when none are):
    /// a strided block cut where a run is split over processes (distributed/halo_plan.hpp).
    ParticleBlock within(Index lo, Index hi) const {
        const Index first = lo <= begin ? 0 : (lo - begin + stride - 1) / stride;
        const Index last = hi <= begin ? 0 : std::min(size(), (hi - begin + stride - 1) / stride);
        if (last <= first) return {begin, begin, stencil, stride};
        return {particle(first), particle(last - 1) + 1, stencil, stride};
    }
};

struct StencilBlocks {
    std::vector<Stencil> stencils;
    std::vector<ParticleBlock> blocks;
    Index particles = 0;  ///< in all blocks (the body's particle count)
    /// Running total of the blocks' cost, in stencil particles (size blocks + 1, from 0): a CSR
    /// particle costs 4 (3.6× a stencil one, measured on the O-grid: docs/performance.md). The
    /// block loops split it evenly among threads (parallelForBlocks, core/parallel.hpp).
    std::vector<std::ptrdiff_t> cost;
    std::size_t bytes() const;
};

/// Partitions the particles [begin, end) of one body into stencil and CSR blocks. Particles
/// flagged in `csrOnly` (per particle; empty = none, e.g. the overset band) always take the
/// CSR path.
StencilBlocks buildStencilBlocks(const PairList& pairs, Index begin, Index end,
                                 const std::vector<std::uint8_t>& csrOnly = {});

}  // namespace gsph
