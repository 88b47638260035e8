// SPDX-License-Identifier: MIT
#include "overset/overset_band.hpp"

#include <algorithm>
#include <array>
#include <deque>

namespace gsph {

void markOversetBand(Reference& ref) {
    const PairList& P = ref.pairs;
    const auto n = static_cast<std::size_t>(ref.size());
    std::vector<std::uint8_t> seed(n, 0);
    bool any = false;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if (ref.space[b] != ref.space[static_cast<std::size_t>(a)]) {
                seed[static_cast<std::size_t>(a)] = seed[b] = 1;
                any = true;
            }
        }
    ref.oversetBand.clear();
    ref.crossOffset.clear();
    ref.crossPair.clear();
    ref.crossOwner.clear();
    ref.oversetCoupled.clear();
    if (!any) return;
    // Transposed pairs: (b, c) in b's list, b and c in different spaces, listed under c in
    // ascending (b, k): the order the force sums them, the same on every run.
    ref.crossOffset.assign(n + 1, 0);
    for (Index b = 0; b < ref.size(); ++b)
        for (Index k = P.begin(b); k < P.end(b); ++k) {
            const auto c = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if (ref.space[c] != ref.space[static_cast<std::size_t>(b)]) ++ref.crossOffset[c + 1];
        }
    for (std::size_t c = 0; c < n; ++c) ref.crossOffset[c + 1] += ref.crossOffset[c];
    ref.crossPair.resize(static_cast<std::size_t>(ref.crossOffset[n]));
    ref.crossOwner.resize(ref.crossPair.size());
    std::vector<Index> fill(ref.crossOffset.begin(), ref.crossOffset.end() - 1);
    for (Index b = 0; b < ref.size(); ++b)
        for (Index k = P.begin(b); k < P.end(b); ++k) {
            const auto c = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if (ref.space[c] == ref.space[static_cast<std::size_t>(b)]) continue;
            const auto slot = static_cast<std::size_t>(fill[c]++);
            ref.crossPair[slot] = k;
            ref.crossOwner[slot] = b;
        }
    double hMax = 0.0;
    for (std::size_t a = 0; a < n; ++a)
        if (seed[a] != 0) hMax = std::max(hMax, ref.smoothingLength[a]);
    const double reach2 = (2.0 * hMax) * (2.0 * hMax);
    // Breadth-first from every seed through the pairs, each particle remembering the seed it
    // was reached from; serial and in index order, so the band is the same on every run.
    ref.oversetBand.assign(n, 0);
    std::vector<Index> from(n, -1);
    std::deque<Index> queue;
    for (std::size_t a = 0; a < n; ++a)
        if (seed[a] != 0) {
            ref.oversetBand[a] = Reference::kBandInterior;
            from[a] = static_cast<Index>(a);
            queue.push_back(static_cast<Index>(a));
        }
    // Particles whose support reaches a free face of their space's lattice box: their Piola sum
    // is the face's traction σn, not zero. A face is an interface, not free, when a transient
    // neighbour lies beyond it.
    const int dim = ref.dim.value;
    std::vector<std::array<std::array<bool, 2>, 3>> covered(ref.spaces.size());
    for (auto& faces : covered)
        for (auto& side : faces) side = {false, false};
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const auto s = static_cast<std::size_t>(ref.space[ia]);
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if (ref.space[b] == ref.space[ia]) continue;
            const Vec3 thetaB =
                ref.theta[ia] -
                P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])]
                    .thetaOffset;
            for (int d = 0; d < dim; ++d) {
                const double extent =
                    ref.spaces[s].cells[static_cast<std::size_t>(d)] * ref.spaces[s].dtheta;
                if (thetaB[d] < 0.0) covered[s][static_cast<std::size_t>(d)][0] = true;
                if (thetaB[d] > extent) covered[s][static_cast<std::size_t>(d)][1] = true;
            }
        }
    }
    const auto nearFreeFace = [&](std::size_t a) {
        const auto s = static_cast<std::size_t>(ref.space[a]);
        const LatticeSpace& L = ref.spaces[s];
        const double support = 2.0 * ref.kappa * L.dtheta;
        for (int d = 0; d < dim; ++d) {
            const auto id = static_cast<std::size_t>(d);
            if (L.periodic[id]) continue;
            const double t = ref.theta[a][d], extent = L.cells[id] * L.dtheta;
            if ((t < support && !covered[s][id][0]) || (t > extent - support && !covered[s][id][1]))
                return true;
        }
        return false;
    };
    while (!queue.empty()) {
        const Index a = queue.front();
        queue.pop_front();
        const Vec3& origin = ref.X[static_cast<std::size_t>(from[static_cast<std::size_t>(a)])];
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if (ref.oversetBand[b] != 0 || (ref.X[b] - origin).squaredNorm() > reach2) continue;
            ref.oversetBand[b] = Reference::kBandInterior;
            from[b] = from[static_cast<std::size_t>(a)];
            queue.push_back(static_cast<Index>(b));
        }
    }
    for (std::size_t a = 0; a < n; ++a)
        if (ref.oversetBand[a] != 0 && nearFreeFace(a))
            ref.oversetBand[a] = Reference::kBandNearFreeFace;
    ref.oversetCoupled.assign(n, 0);
    for (std::size_t a = 0; a < n; ++a)
        ref.oversetCoupled[a] = seed[a] != 0 || ref.oversetBand[a] != 0 ? 1 : 0;
}

}  // namespace gsph
