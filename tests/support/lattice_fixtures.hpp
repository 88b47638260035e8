// SPDX-License-Identifier: MIT
// Shared helpers of the tests: analytic spaces built to the point where a test can use them,
// interior-particle selection, and a stress-free elastic material.
#pragma once

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "materials/material.hpp"
#include "neighbors/theta_search.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "spaces/metric.hpp"

namespace gsph::testing {

/// Reference over `map` with pairs and geometry built.
inline Reference builtReference(const AnalyticMap& map, int dim, std::array<int, 3> cells,
                                double kappa = 1.2, double density = 1000.0) {
    Reference ref = latticeReference(map, dim, cells, density, kappa);
    buildPairs(ref);
    computeGeometry(ref);
    return ref;
}

/// Appends the particles of `from` (a reference of one lattice space, before its pairs) to
/// `into` as a new space of body `body`; bodies must come in order (Reference invariant).
inline void appendSpace(Reference& into, const Reference& from, Index body) {
    const auto space = static_cast<Index>(into.spaces.size());
    into.spaces.push_back(from.spaces[0]);
    for (std::size_t p = 0; p < from.X.size(); ++p) {
        into.X.push_back(from.X[p]);
        into.theta.push_back(from.theta[p]);
        into.density.push_back(from.density[p]);
        into.volume.push_back(from.volume[p]);
        into.body.push_back(body);
        into.space.push_back(space);
    }
}

/// Particles whose lattice distance to every non-periodic boundary is at least `margin` cells.
inline std::vector<Index> interiorParticles(const Reference& ref, int margin) {
    const LatticeSpace& s = ref.spaces[0];
    std::vector<Index> out;
    for (Index a = 0; a < ref.size(); ++a) {
        bool inside = true;
        for (int d = 0; d < ref.dim.value; ++d) {
            if (s.periodic[static_cast<std::size_t>(d)]) continue;
            const int i =
                static_cast<int>(std::floor(ref.theta[static_cast<std::size_t>(a)][d] / s.dtheta));
            if (i < margin || i >= s.cells[static_cast<std::size_t>(d)] - margin) inside = false;
        }
        if (inside) out.push_back(a);
    }
    return out;
}

/// Cells of one kernel support: ⌈2κ⌉.
inline int supportCells(const Reference& ref) {
    return static_cast<int>(std::ceil(2.0 * ref.kappa));
}

/// The force on every particle at the start of a run, f = m a, under the state set on `sim`.
inline std::vector<Vec3> forcesUnder(Simulation& sim) {
    sim.start();
    std::vector<Vec3> f(sim.state().acceleration.size());
    for (std::size_t a = 0; a < f.size(); ++a)
        f[a] = sim.reference().mass[a] * sim.state().acceleration[a];
    return f;
}

/// The two arrays hold the same bytes.
template <class T>
bool bitIdentical(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace gsph::testing
