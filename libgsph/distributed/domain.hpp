// SPDX-License-Identifier: MIT
// A run split over processes (ranks): what the integrator needs to know of the split.
//
// Every process holds the whole reference configuration and state arrays indexed by the global
// particle index, and advances only its own particles, a contiguous range cut between stencil
// blocks or inside a strided one (distributed/halo_plan.hpp): every particle keeps the path
// (stencil or CSR) and the arithmetic of the serial run, so its bits do not depend on the
// process count.
// Within a step a particle reads its neighbours twice: their x, v after the drift (for F, Ḟ,
// and the bonds' stretch) and their force factors after the stress update (for the pair forces;
// with bonds that break, also their damage and stress); shareGhosts brings those entries of the
// neighbours another process owns (its ghosts). Bonds break where their particle is owned; each
// process then takes its ghosts' rows of the bond flags from their owners (shareGhostRows), so
// every particle it reads sees its surviving bonds as the serial run does. Contact between bodies
// searches the particles within reach of the contact zone in the current configuration: each
// process lists its own, and shareListed brings it the others' within reach. A nonlocal damage
// averages its driver over a material length, beyond the pairs: the driver has a halo of its
// own (addHalo), exchanged before the average. The global minimum of Δt is exact; so are the
// sums of the energy ledger and the contact and wall totals: each process sums its particles'
// terms exactly (core/exact_sum.hpp), the processes add those integers, and the total is rounded
// once, so they do not depend on the split. gather gives process 0 every particle's state for the
// files it writes.
//
// This base class is the serial run: one process owning every particle, nothing to exchange.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"
#include "distributed/halo_plan.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// The points of a step where neighbours' entries are read (tags of the exchanges). The
/// damage driver's readers are the nonlocal average's (addHalo), not the pairs'.
enum class GhostColumns { Motion = 1, ForceFactors = 2, BondRows = 3, DamageDriver = 4 };

/// A per-particle array whose ghosts' entries an exchange overwrites: entry a occupies
/// `entryBytes` bytes at data + a·entryBytes (a column of doubles, or an array of Vec3, Mat3).
struct GhostArray {
    void* data = nullptr;
    std::size_t entryBytes = 0;
};

template <class T>
GhostArray ghostArray(T* entries) {
    return {entries, sizeof(T)};
}

class Domain {
  public:
    virtual ~Domain() = default;
    /// Called once, before the first step, with each body's blocks (in body order): splits the
    /// particles and returns this process's range. `cutStrided`: a cut may split a strided
    /// block (distributed/halo_plan.hpp); not when bonds can break, since a block with a broken
    /// bond takes the CSR path as a whole, and its parts would each choose for themselves.
    virtual ParticleRange split(const Reference& ref, const std::vector<StencilBlocks>& blocks,
                                bool cutStrided) {
        (void)blocks;
        (void)cutStrided;
        return {0, ref.size()};
    }
    /// Number of processes.
    virtual int processes() const { return 1; }
    /// One line on the split for the run's log (after split(); empty when serial).
    virtual std::string describe() const { return {}; }
    /// Whether this process writes the run's files (process 0).
    virtual bool writesFiles() const { return true; }
    /// Overwrites this process's ghosts' entries of every array with their owners' values;
    /// `arrays` in the same order on every process.
    virtual void shareGhosts(GhostColumns which, std::span<const GhostArray> arrays) {
        (void)which;
        (void)arrays;
    }
    /// Gives the exchanges tagged `which` a halo of their own, planned from `reads` instead of
    /// the pairs (after split(); collective). `what` names the readers in describe().
    virtual void addHalo(GhostColumns which, const Reads& reads, const std::string& what) {
        (void)which, (void)reads, (void)what;
    }
    /// This process's ghosts, ascending (after split(); empty when serial).
    virtual std::span<const Index> ghosts() const { return {}; }
    /// Overwrites this process's ghosts' rows of a per-pair array (one byte per entry of
    /// ref.pairs, the CSR order of split()'s reference) with their owners' (collective).
    virtual void shareGhostRows(std::span<std::uint8_t> perPair) { (void)perPair; }
    /// Every process lists some of its own particles, ascending (`mine`), and gets those of
    /// every other process's that lie within `reach` of the box of its own listed positions
    /// (collective): x[b], and flags[b] unless flags is empty, for each such b, and those b in
    /// `received`. The particles a search in the current configuration can meet (contact): a
    /// listed particle sees every other one within reach.
    virtual void shareListed(std::span<const Index> mine, double reach, std::vector<Vec3>& x,
                             std::vector<std::uint8_t>& flags, std::vector<Index>& received) {
        (void)mine, (void)reach, (void)x, (void)flags;
        received.clear();
    }
    /// The bytes this process has sent so far: its particles' columns to the processes whose
    /// ghosts they are (shareGhosts, shareGhostRows), and its contact-zone particles
    /// (shareListed).
    struct BytesSent {
        double ghosts = 0.0, contact = 0.0;
    };
    virtual BytesSent bytesSent() const { return {}; }
    /// The minimum over the processes (exact).
    virtual double minimum(double local) { return local; }
    /// Each value's minimum over the processes (exact).
    virtual void minimum(std::span<double> values) { (void)values; }
    /// Each exact sum summed over the processes (exact: the same for any process count).
    virtual void sum(std::span<ExactSum> values) { (void)values; }
    /// The exact sum over the processes of each one's `partial`, rounded once.
    double total(ExactSum partial) {
        sum(std::span<ExactSum>(&partial, 1));
        return partial.value();
    }
    /// True when it is true on some process.
    virtual bool any(bool local) { return local; }
    /// Process 0's state gets every process's particles (per-particle arrays, and the per-pair
    /// arrays by the rows of each process's particles; the scalars are the same everywhere).
    virtual void gather(State& state) { (void)state; }
};

}  // namespace gsph
