// SPDX-License-Identifier: MIT
// The split of a run over processes and the ghosts each one needs (distributed/domain.hpp).
//
// Split: contiguous particle ranges of about equal cost (StencilBlocks::cost, the measure the
// threads already share the block loops by), cut only where no block of consecutive particles
// straddles the cut: each cut is the first such place at or past its share of the cost. A
// lattice's corner-column blocks (stride a row, up to kMaxBlock rows) may be cut, into two
// strided blocks with the same stencil, each at least a strip long (kMinStencilRun): every
// particle keeps the path and the arithmetic of the serial run. Particles are numbered space by
// space, lattice row by row, so a range is a set of slabs of the bodies' lattices. Ghosts: every
// particle another process owns that one of this process's particles reads in a step: its
// pairs' neighbours (Reference::pairs) and the particles whose transposed cross-space pairs it
// sums (Reference::crossOwner); a read beyond the pairs (the nonlocal damage's average over a
// material length) gets a halo of its own, planned alike from its own relation. Computed once,
// in the reference configuration, by every process for every other (each holds the whole
// reference): no message is needed to agree on who sends what.
#pragma once

#include <functional>
#include <vector>

#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// cuts[r], cuts[r + 1]: the particles process r owns (size processes + 1, cuts[0] = 0, back()
/// = the particle count). Throws InputError when the blocks allow fewer than `processes`
/// non-empty ranges. A process owns its range's part of a strided block that a cut splits
/// (ParticleBlock::within); `cutStrided` false keeps every block whole.
std::vector<Index> cutByCost(const std::vector<StencilBlocks>& bodies, Index particles,
                             int processes, bool cutStrided = true);

/// The cost of each process's range (size processes).
std::vector<std::ptrdiff_t> costsOf(const std::vector<StencilBlocks>& bodies,
                                    const std::vector<Index>& cuts);

/// What this process exchanges with one other: the particles it sends (its own, that the other
/// reads) and those it receives (the other's, that it reads), both ascending.
struct HaloPeer {
    int process = 0;
    std::vector<Index> send, receive;
};

/// What particle a reads in a step, appended to `out` (any order, repeats allowed).
using Reads = std::function<void(Index a, std::vector<Index>& out)>;

/// What a particle reads through the reference's pairs: its pairs' neighbours and the owners of
/// the transposed cross-space pairs it sums.
Reads pairReads(const Reference& ref);

/// The peers of `process` (those it exchanges anything with), ascending, when every particle
/// reads what `reads` says.
std::vector<HaloPeer> planHalo(const Reads& reads, const std::vector<Index>& cuts, int process);

}  // namespace gsph
