// SPDX-License-Identifier: MIT
// Neighbour search in θ-space, run once on the reference configuration (DESIGN §3).
//
// Pairs join particles of the same body whose θ-distance in the first particle's home space
// (minimum image across periodic indices) is below that space's kernel support 2h, h = κΔθ:
// its home particles, and the transient particles of other spaces that have θ there
// (Reference::overset, DESIGN §6), each with its own quadrature weight ω. Two methods give the
// same PairList: a cell list on the θ-lattice (the default: faster on lattices, see
// tests/bench/bench_neighbors.cpp) and a nanoflann k-d tree. Results are independent of the
// thread count and of the method.
#pragma once

#include "particles/reference.hpp"

namespace gsph {

enum class SearchMethod { CellList, KdTree };

/// Builds ref.pairs (CSR, sorted neighbours, kernel table). Throws InputError on an empty or
/// inconsistent reference (θ outside its space, unknown space id).
void buildPairs(Reference& ref, SearchMethod method = SearchMethod::CellList);

}  // namespace gsph
