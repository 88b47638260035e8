// SPDX-License-Identifier: MIT
#include "failure/nonlocal_damage.hpp"

#include <algorithm>
#include <nanoflann.hpp>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// The body's reference positions as nanoflann's point cloud.
struct Cloud {
    const Vec3* X;
    std::size_t n;
    std::size_t kdtree_get_point_count() const { return n; }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return X[i][static_cast<int>(d)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};
using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;

}  // namespace

NonlocalAverage::NonlocalAverage(const std::vector<Vec3>& X, const std::vector<double>& V,
                                 Index begin, Index end, double length)
    : begin_(begin), end_(end) {
    if (!(length > 0.0))
        throw InputError("nonlocal damage length must be > 0, got " + std::to_string(length));
    const auto n = static_cast<std::size_t>(end - begin);
    const Cloud cloud{X.data() + begin, n};
    Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    const double radius2 = length * length;
    // Per particle its neighbours within ℓ in index order (so sums run in a fixed order).
    std::vector<std::vector<std::pair<std::uint32_t, double>>> found(n);
    parallelFor(static_cast<std::ptrdiff_t>(n), [&](std::ptrdiff_t i) {
        auto& list = found[static_cast<std::size_t>(i)];
        tree.radiusSearch(X[static_cast<std::size_t>(begin + i)].data(), radius2, list,
                          nanoflann::SearchParams(32, 0.0f, false));
        std::sort(list.begin(), list.end());
    });
    offset_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + found[i].size();
    neighbor_.resize(offset_[n]);
    weight_.resize(offset_[n]);
    parallelFor(static_cast<std::ptrdiff_t>(n), [&](std::ptrdiff_t i) {
        const auto ii = static_cast<std::size_t>(i);
        double total = 0.0;
        std::size_t k = offset_[ii];
        for (const auto& [j, r2] : found[ii]) {
            const double q = 1.0 - r2 / radius2;
            neighbor_[k] = begin + static_cast<Index>(j);
            weight_[k] = V[static_cast<std::size_t>(begin) + j] * q * q;
            total += weight_[k++];
        }
        for (k = offset_[ii]; k < offset_[ii + 1]; ++k) weight_[k] /= total;
    });
}

double NonlocalAverage::weight(Index a, Index b) const {
    const auto i = static_cast<std::size_t>(a - begin_);
    for (std::size_t k = offset_[i]; k < offset_[i + 1]; ++k)
        if (neighbor_[k] == b) return weight_[k];
    return 0.0;
}

}  // namespace gsph
