// SPDX-License-Identifier: MIT
// A run split over processes (ranks): what the integrator needs to know of the split.
//
// Every process holds the whole reference configuration and state arrays indexed by the global
// particle index, and advances only its own particles, a contiguous range cut at stencil-block
// boundaries (distributed/halo_plan.hpp): its blocks keep the paths (stencil or CSR) and the
// arithmetic of the serial run, so each particle's bits do not depend on the process count.
// Within a step a particle reads its neighbours twice: their x, v after the drift (for F, Ḟ)
// and their force factors after the stress update (for the pair forces); shareGhosts brings
// those columns of the neighbours another process owns (its ghosts). Contact between bodies
// searches every particle's current position: shareAll gives each process all of them. The global
// minimum of Δt is exact; the sums of the energy ledger add the processes' partial sums, so they
// depend on the split at round-off (the state does not read them). gather gives process 0 every
// particle's state for the files it writes.
//
// This base class is the serial run: one process owning every particle, nothing to exchange.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// The two points of a step where neighbours' columns are read (tags of the exchanges).
enum class GhostColumns { Motion = 1, ForceFactors = 2 };

class Domain {
  public:
    virtual ~Domain() = default;
    /// Called once, before the first step, with each body's blocks (in body order): splits the
    /// particles and returns this process's range.
    virtual ParticleRange split(const Reference& ref, const std::vector<StencilBlocks>& blocks) {
        (void)blocks;
        return {0, ref.size()};
    }
    /// Number of processes.
    virtual int processes() const { return 1; }
    /// One line on the split for the run's log (after split(); empty when serial).
    virtual std::string describe() const { return {}; }
    /// Whether this process writes the run's files (process 0).
    virtual bool writesFiles() const { return true; }
    /// Overwrites this process's ghosts' entries of every column (one double per particle,
    /// indexed by particle) with their owners' values; `columns` in the same order on every
    /// process.
    virtual void shareGhosts(GhostColumns which, std::span<double* const> columns) {
        (void)which;
        (void)columns;
    }
    /// Every process gets every process's entries of a per-particle array (collective): the
    /// positions a search in the current configuration (contact between bodies) reads.
    virtual void shareAll(std::vector<Vec3>& perParticle) { (void)perParticle; }
    /// The minimum over the processes (exact).
    virtual double minimum(double local) { return local; }
    /// Each value summed over the processes.
    virtual void sum(std::span<double> values) { (void)values; }
    /// True when it is true on some process.
    virtual bool any(bool local) { return local; }
    /// Process 0's state gets every process's particles (per-particle arrays; the scalars are
    /// the same everywhere).
    virtual void gather(State& state) { (void)state; }
};

}  // namespace gsph
