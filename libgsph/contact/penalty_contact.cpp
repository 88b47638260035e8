// SPDX-License-Identifier: MIT
#include "contact/penalty_contact.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

std::vector<double> contactStiffness(const Reference& ref, const std::vector<double>& pWaveSpeed2,
                                     double penalty) {
    if (!(penalty > 0.0)) throw InputError("contact penalty factor must be > 0");
    std::vector<double> k(static_cast<std::size_t>(ref.size()));
    for (std::size_t a = 0; a < k.size(); ++a)
        k[a] = penalty * ref.mass[a] * pWaveSpeed2[a] / (ref.spacing[a] * ref.spacing[a]);
    return k;
}

PenaltyContact::PenaltyContact(const Reference& ref, std::vector<double> stiffness,
                               const ContactOptions& options)
    : ref_(&ref), stiffness_(std::move(stiffness)) {
    if (!(options.distance > 0.0)) throw InputError("contact distance factor must be > 0");
    const auto n = static_cast<std::size_t>(ref.size());
    const bool severalBodies = n > 0 && std::any_of(ref.body.begin(), ref.body.end(),
                                                    [&](Index b) { return b != ref.body.front(); });
    active_ = options.betweenBodies && severalBodies;
    if (!active_) return;
    radius_.resize(n);
    double largest = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
        radius_[a] = 0.5 * options.distance * ref.spacing[a];
        largest = std::max(largest, radius_[a]);
    }
    // Cells at least as wide as the largest contact distance: every pair in contact lies in
    // neighbouring cells.
    cellSize_ = 2.0 * largest;
    // Buckets: a power of two ≥ 2n keeps the expected load of a bucket below one cell's.
    std::size_t buckets = 1;
    while (buckets < 2 * n) buckets *= 2;
    cell_.resize(n);
    bucket_.resize(n);
    bucketStart_.resize(buckets + 2);  // the last bucket holds particles with a non-finite x
    sorted_.resize(n);
    energy_.resize(n);
    pairCount_.resize(n);
}

std::size_t PenaltyContact::bucketOf(const Cell& c) const {
    // Spatial hash of the cell's integer coordinates (large odd multipliers, Teschner et al.
    // 2003); collisions only add candidates, which the cell check below rejects.
    const auto h = static_cast<std::uint64_t>(c[0]) * 73856093ULL ^
                   static_cast<std::uint64_t>(c[1]) * 19349663ULL ^
                   static_cast<std::uint64_t>(c[2]) * 83492791ULL;
    return static_cast<std::size_t>(h & (bucketStart_.size() - 3));
}

// Counting sort of the particles by bucket (sequential: O(n) and a fixed order).
void PenaltyContact::build(const std::vector<Vec3>& x) {
    const std::size_t n = x.size(), nowhere = bucketStart_.size() - 2;
    std::fill(bucketStart_.begin(), bucketStart_.end(), 0);
    for (std::size_t a = 0; a < n; ++a) {
        if (!x[a].allFinite()) {
            bucket_[a] = static_cast<std::uint32_t>(nowhere);
        } else {
            for (int d = 0; d < 3; ++d)
                cell_[a][static_cast<std::size_t>(d)] =
                    static_cast<std::int64_t>(std::floor(x[a][d] / cellSize_));
            bucket_[a] = static_cast<std::uint32_t>(bucketOf(cell_[a]));
        }
        ++bucketStart_[bucket_[a] + 1];
    }
    for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
    for (std::size_t a = 0; a < n; ++a)
        sorted_[static_cast<std::size_t>(bucketStart_[bucket_[a]]++)] = static_cast<Index>(a);
    // The fill advanced each start to the next bucket's start: shift back.
    for (std::size_t b = bucketStart_.size() - 1; b > 0; --b) bucketStart_[b] = bucketStart_[b - 1];
    bucketStart_[0] = 0;
}

double PenaltyContact::addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force,
                                 std::vector<double>& frequency2) {
    pairs_ = 0;
    if (!active_) return 0.0;
    build(x);
    const Reference& ref = *ref_;
    const int zReach = ref.dim.value == 2 ? 0 : 1;
    parallelFor(ref.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        energy_[ia] = 0.0;
        pairCount_[ia] = 0;
        if (!x[ia].allFinite()) return;
        const Index body = ref.body[ia];
        const double ka = stiffness_[ia], ma = ref.mass[ia];
        Vec3 f = Vec3::Zero();
        double w2 = 0.0, u = 0.0;
        int count = 0;
        for (int dz = -zReach; dz <= zReach; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Cell c = {cell_[ia][0] + dx, cell_[ia][1] + dy, cell_[ia][2] + dz};
                    const std::size_t bucket = bucketOf(c);
                    for (Index j = bucketStart_[bucket]; j < bucketStart_[bucket + 1]; ++j) {
                        const auto ib =
                            static_cast<std::size_t>(sorted_[static_cast<std::size_t>(j)]);
                        if (ref.body[ib] == body || cell_[ib] != c) continue;
                        const Vec3 d = x[ia] - x[ib];
                        const double r2 = d.squaredNorm(), dab = radius_[ia] + radius_[ib];
                        if (!(r2 < dab * dab) || r2 == 0.0) continue;
                        const double r = std::sqrt(r2), gap = dab - r;
                        const double kb = stiffness_[ib];
                        const double kab = ka * kb / (ka + kb);  // springs in series
                        f += (kab * gap / r) * d;
                        u += 0.25 * kab * gap * gap;  // half of the pair's ½ k gap²
                        w2 += kab * (1.0 / ma + 1.0 / std::sqrt(ma * ref.mass[ib]));
                        ++count;
                    }
                }
        force[ia] += f;
        frequency2[ia] += w2;
        energy_[ia] = u;
        pairCount_[ia] = count;
    });
    long counted = 0;
    for (std::int32_t c : pairCount_) counted += c;
    pairs_ = counted / 2;
    return deterministicSum(
        ref.size(), 0.0, [&](Index a) { return energy_[static_cast<std::size_t>(a)]; }, partial_);
}

}  // namespace gsph
