// SPDX-License-Identifier: MIT
// Two-space references for the overset tests (DESIGN §6), built from analytic maps so the
// library is verified before any mesh: two Cartesian blocks of one body, abutting at x = Lx,
// the second `ratio` times finer. Every particle within one kernel support of the other
// space (in that space's θ) becomes transient there, with θ from the inverse map and
// ω = V / det(∂X/∂θ) of that space — what gsph-preproc stores in /overset.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "neighbors/theta_search.hpp"
#include "spaces/analytic_maps.hpp"
#include "spaces/metric.hpp"
#include "support/lattice_fixtures.hpp"

namespace gsph::testing {

struct TwoBlocks {
    Reference ref;
    double coarse = 0.0, fine = 0.0;  ///< spacings [m]
    Vec3 size = Vec3::Zero();         ///< the whole body: [0, size]
};

/// Block 0: [0, Lx] × [0, H] (× [0, H]), n cells across H; block 1: [Lx, 2Lx] × …, `ratio`
/// times finer. Pairs and geometry built (κ as given).
inline TwoBlocks twoBlocks(int dim, int n, int ratio, double kappa = 1.2, double Lx = 1.0,
                           double H = 0.5, double density = 7800.0) {
    TwoBlocks out;
    out.coarse = H / n;
    out.fine = out.coarse / ratio;
    const int nx = static_cast<int>(std::lround(Lx / out.coarse));
    const double depth = dim == 3 ? H : 0.0;
    out.size = Vec3(2 * Lx, H, depth);
    const std::array<int, 3> cellsA = {nx, n, dim == 3 ? n : 1};
    const std::array<int, 3> cellsB = {nx * ratio, n * ratio, dim == 3 ? n * ratio : 1};
    Reference a = latticeReference(gradedBoxMap(Vec3(Lx, H, dim == 3 ? H : 1.0), {}), dim, cellsA,
                                   density, kappa);
    const Reference b =
        latticeReference(gradedBoxMap(Vec3(Lx, H, dim == 3 ? H : 1.0), {}, Vec3(Lx, 0, 0)), dim,
                         cellsB, density, kappa);
    appendSpace(a, b, 0);
    // θ of X in each block's space (Δθ = 1: θ = (X − origin)/spacing; z stays 0 in 2-D).
    const double spacing[2] = {out.coarse, out.fine};
    const Vec3 origin[2] = {Vec3::Zero(), Vec3(Lx, 0, 0)};
    const auto thetaIn = [&](int s, const Vec3& X) {
        Vec3 t = (X - origin[s]) / spacing[s];
        if (dim == 2) t[2] = 0.0;
        return t;
    };
    const double support = 2.0 * kappa;
    for (std::size_t p = 0; p < a.X.size(); ++p) {
        const int home = a.space[p];
        const int other = 1 - home;
        const Vec3 t = thetaIn(other, a.X[p]);
        bool near = false;
        for (std::size_t q = 0; q < a.X.size() && !near; ++q)
            near = a.space[q] == other && (a.theta[q] - t).norm() < support;
        if (!near) continue;
        const double det = std::pow(spacing[other], dim);
        a.overset.push_back({static_cast<Index>(p), other, t, a.volume[p] / det});
    }
    buildPairs(a);
    computeGeometry(a);
    out.ref = std::move(a);
    return out;
}

/// The plain pairwise form across the interface (a baseline): the corrected interface weights
/// (overset/interface_weights.hpp) dropped.
inline void withoutInterfaceCorrections(Reference& ref) {
    std::fill(ref.correctionBegin.begin(), ref.correctionBegin.end(), Index{-1});
}

}  // namespace gsph::testing
