// SPDX-License-Identifier: MIT
#include "contact/penalty_contact.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "spaces/metric.hpp"

namespace gsph {

std::vector<double> contactStiffness(const Reference& ref, const std::vector<double>& pWaveSpeed2,
                                     double penalty) {
    if (!(penalty > 0.0)) throw InputError("contact penalty factor must be > 0");
    std::vector<double> k(static_cast<std::size_t>(ref.size()));
    for (std::size_t a = 0; a < k.size(); ++a)
        k[a] = penalty * ref.mass[a] * pWaveSpeed2[a] / (ref.spacing[a] * ref.spacing[a]);
    return k;
}

ContactShapes contactShapes(const Reference& ref, double distance) {
    if (!(distance > 0.0)) throw InputError("contact distance factor must be > 0");
    const auto n = static_cast<std::size_t>(ref.size());
    ContactShapes shapes;
    shapes.S.resize(n);
    shapes.largestRadius.resize(n);
    parallelFor(ref.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const Mat3 M = particleMetric(ref, a).M;
        const double half =
            0.5 * distance * ref.spaces[static_cast<std::size_t>(ref.space[ia])].dtheta;
        // 2-D: M's zz entry is the out-of-plane identity; n never has a z part, so S_zz only
        // has to be finite, and the largest semi-axis is the in-plane one.
        const double largest =
            ref.dim.value == 3
                ? Eigen::JacobiSVD<Mat3>(M).singularValues()[0]
                : Eigen::JacobiSVD<Eigen::Matrix2d>(M.topLeftCorner<2, 2>()).singularValues()[0];
        shapes.S[ia] = (half * M).inverse();
        shapes.largestRadius[ia] = half * largest;
    });
    return shapes;
}

PenaltyContact::PenaltyContact(const Reference& ref, std::vector<double> stiffness,
                               ContactShapes shapes, const ContactOptions& options)
    : ref_(&ref), shapes_(std::move(shapes)), stiffness_(std::move(stiffness)) {
    const auto n = static_cast<std::size_t>(ref.size());
    owned_ = {0, ref.size()};
    const bool severalBodies = n > 0 && std::any_of(ref.body.begin(), ref.body.end(),
                                                    [&](Index b) { return b != ref.body.front(); });
    betweenBodies_ = options.betweenBodies && severalBodies;
    selfContact_ = options.selfContact && n > 0;
    active_ = betweenBodies_ || selfContact_;
    if (!active_) return;
    const double largest =
        *std::max_element(shapes_.largestRadius.begin(), shapes_.largestRadius.end());
    // Cells at least as wide as the largest contact distance: every pair in contact lies in
    // neighbouring cells.
    cellSize_ = 2.0 * largest;
    // Buckets: a power of two ≥ 2n keeps the expected load of a bucket below one cell's.
    std::size_t buckets = 1;
    while (buckets < 2 * n) buckets *= 2;
    for (Index a = 0; a < ref.size();) {
        Index end = a;
        while (end < ref.size() &&
               ref.body[static_cast<std::size_t>(end)] == ref.body[static_cast<std::size_t>(a)])
            ++end;
        ranges_.emplace_back(a, end);
        a = end;
    }
    const Index largestId = *std::max_element(ref.body.begin(), ref.body.end());
    rangeOfBody_.assign(static_cast<std::size_t>(largestId) + 1, 0);
    for (std::size_t r = 0; r < ranges_.size(); ++r)
        rangeOfBody_[static_cast<std::size_t>(
            ref.body[static_cast<std::size_t>(ranges_[r].first)])] = r;
    boxLow_.resize(ranges_.size());
    boxHigh_.resize(ranges_.size());
    damagedLow_.resize(ranges_.size());
    damagedHigh_.resize(ranges_.size());
    candidate_.resize(n);
    if (selfContact_) damaged_.assign(n, 0);
    cell_.resize(n);
    bucket_.resize(n);
    bucketStart_.resize(buckets + 2);  // the last bucket holds the particles out of reach
    sorted_.resize(n);
    energy_.resize(n);
    pairCount_.resize(n);
    forceByBody_.resize(n * ranges_.size());
}

std::size_t PenaltyContact::bucketOf(const Cell& c) const {
    // Spatial hash of the cell's integer coordinates (large odd multipliers, Teschner et al.
    // 2003); collisions only add candidates, which the cell check below rejects.
    const auto h = static_cast<std::uint64_t>(c[0]) * 73856093ULL ^
                   static_cast<std::uint64_t>(c[1]) * 19349663ULL ^
                   static_cast<std::uint64_t>(c[2]) * 83492791ULL;
    return static_cast<std::size_t>(h & (bucketStart_.size() - 3));
}

// Which particles have lost a bond (self-contact's pairs need one of them).
void PenaltyContact::markDamaged(const std::vector<std::uint8_t>& bondIntact) {
    const PairList& P = ref_->pairs;
    anyDamaged_ = false;
    if (!selfContact_ || bondIntact.empty()) return;
    // Each particle from its own bonds; split, the flags of the other processes' particles
    // come with their positions (markCandidates).
    parallelFor(owned_, [&](Index a) {
        std::uint8_t lost = 0;
        for (Index k = P.begin(a); k < P.end(a) && !lost; ++k)
            lost = bondIntact[static_cast<std::size_t>(k)] == 0;
        damaged_[static_cast<std::size_t>(a)] = lost;
    });
    anyDamaged_ = std::any_of(damaged_.begin() + owned_.begin, damaged_.begin() + owned_.end,
                              [](std::uint8_t d) { return d; });
    if (split()) anyDamaged_ = domain_->any(anyDamaged_);
}

// The pair (a, b) of a's list, or −1 if b is not a's neighbour (a's list is sorted).
Index PenaltyContact::pairOf(Index a, Index b) const {
    const PairList& P = ref_->pairs;
    const auto first = P.neighbor.begin() + P.begin(a), last = P.neighbor.begin() + P.end(a);
    const auto it = std::lower_bound(first, last, b);
    return it != last && *it == b ? static_cast<Index>(it - P.neighbor.begin()) : -1;
}

void PenaltyContact::recordSeparations(const std::vector<Vec3>& x,
                                       const std::vector<std::uint8_t>& bondIntact,
                                       std::vector<double>& separation) const {
    if (!selfContact_) return;
    const PairList& P = ref_->pairs;
    if (separation.size() != bondIntact.size()) separation.assign(bondIntact.size(), 0.0);
    if (!anyDamaged_) return;
    const Reference& ref = *ref_;
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        if (!damaged_[ia]) return;
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto ik = static_cast<std::size_t>(k);
            if (bondIntact[ik]) continue;
            const auto b = static_cast<std::size_t>(P.neighbor[ik]);
            separation[ik] = std::min((ref.X[ia] - ref.X[b]).norm(),
                                      std::max(separation[ik], (x[ia] - x[b]).norm()));
        }
    });
}

// Which particles can touch another body at all: those inside another body's bounding box
// grown by the largest contact distance (a pair in contact lies within that reach of each
// other, so both ends pass); with self-contact also those inside the box of their own body's
// damaged particles grown alike. Keeps the search to the contact zone (the interior of a plate
// far from the projectile costs a box test, not 27 cells). Split, each process bounds its own
// particles and the boxes are the processes' exact minima and maxima; each marks its own
// candidates and gets the others' positions (and lost-bond flags): every process then searches
// the serial run's candidates, in the same order. Returns the positions the search reads.
const std::vector<Vec3>& PenaltyContact::markCandidates(const std::vector<Vec3>& x) {
    const Vec3 big = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (std::size_t b = 0; b < ranges_.size(); ++b) {
        Vec3 lo = big, hi = -big, damagedLo = big, damagedHi = -big;
        const ParticleRange mine = owned_.within(ranges_[b].first, ranges_[b].second);
        for (Index a = mine.begin; a < mine.end; ++a) {
            const Vec3& xa = x[static_cast<std::size_t>(a)];
            if (!xa.allFinite()) continue;
            lo = lo.cwiseMin(xa);
            hi = hi.cwiseMax(xa);
            if (anyDamaged_ && damaged_[static_cast<std::size_t>(a)]) {
                damagedLo = damagedLo.cwiseMin(xa);
                damagedHi = damagedHi.cwiseMax(xa);
            }
        }
        boxLow_[b] = lo;
        boxHigh_[b] = hi;
        damagedLow_[b] = damagedLo;
        damagedHigh_[b] = damagedHi;
    }
    if (split()) {
        // Maxima as minima of the negatives (exact).
        bounds_.clear();
        for (std::size_t b = 0; b < ranges_.size(); ++b)
            for (int d = 0; d < 3; ++d) {
                bounds_.push_back(boxLow_[b][d]);
                bounds_.push_back(-boxHigh_[b][d]);
                bounds_.push_back(damagedLow_[b][d]);
                bounds_.push_back(-damagedHigh_[b][d]);
            }
        domain_->minimum(bounds_);
        for (std::size_t b = 0, k = 0; b < ranges_.size(); ++b)
            for (int d = 0; d < 3; ++d) {
                boxLow_[b][d] = bounds_[k++];
                boxHigh_[b][d] = -bounds_[k++];
                damagedLow_[b][d] = bounds_[k++];
                damagedHigh_[b][d] = -bounds_[k++];
            }
    }
    for (std::size_t b = 0; b < ranges_.size(); ++b) {
        boxLow_[b] = boxLow_[b].array() - cellSize_;
        boxHigh_[b] = boxHigh_[b].array() + cellSize_;
        damagedLow_[b] = damagedLow_[b].array() - cellSize_;
        damagedHigh_[b] = damagedHigh_[b].array() + cellSize_;
    }
    const auto inside = [&](const Vec3& p, const Vec3& lo, const Vec3& hi) {
        return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    };
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        std::uint8_t near = 0;
        for (std::size_t b = 0; b < ranges_.size() && !near; ++b) {
            const bool own = a >= ranges_[b].first && a < ranges_[b].second;
            near = own ? anyDamaged_ && inside(x[ia], damagedLow_[b], damagedHigh_[b])
                       : betweenBodies_ && inside(x[ia], boxLow_[b], boxHigh_[b]);
        }
        candidate_[ia] = near;
    });
    if (!split()) return x;
    for (Index b : received_) candidate_[static_cast<std::size_t>(b)] = 0;
    listed_.clear();
    for (Index a = owned_.begin; a < owned_.end; ++a) {
        const auto ia = static_cast<std::size_t>(a);
        if (!candidate_[ia]) continue;
        listed_.push_back(a);
        positions_[ia] = x[ia];
    }
    // A pair in contact is closer than the sum of the two largest radii, at most cellSize_.
    domain_->shareListed(listed_, cellSize_, positions_, damaged_, received_);
    for (Index b : received_) candidate_[static_cast<std::size_t>(b)] = 1;
    return positions_;
}

// Counting sort of the candidates by bucket (sequential: O(n) and a fixed order).
const std::vector<Vec3>& PenaltyContact::build(const std::vector<Vec3>& current) {
    const std::vector<Vec3>& x = markCandidates(current);
    const std::size_t n = x.size(), nowhere = bucketStart_.size() - 2;
    std::fill(bucketStart_.begin(), bucketStart_.end(), 0);
    for (std::size_t a = 0; a < n; ++a) {
        if (!candidate_[a]) {
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
    return x;
}

double PenaltyContact::addForces(const std::vector<Vec3>& current, std::vector<Vec3>& force,
                                 std::vector<double>& frequency2,
                                 const std::vector<std::uint8_t>& bondIntact,
                                 const std::vector<double>& separation) {
    pairs_ = 0;
    if (!active_) return 0.0;
    markDamaged(bondIntact);
    const std::vector<Vec3>& x = build(current);
    const Reference& ref = *ref_;
    const ContactShapes& shape = shapes_;
    const int zReach = ref.dim.value == 2 ? 0 : 1;
    const std::size_t bodies = ranges_.size();
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        energy_[ia] = 0.0;
        pairCount_[ia] = 0;
        if (!candidate_[ia]) return;
        Vec3* byBody = &forceByBody_[ia * bodies];
        for (std::size_t j = 0; j < bodies; ++j) byBody[j].setZero();
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
                        const bool sameBody = ref.body[ib] == body;
                        if ((sameBody ? !anyDamaged_ || ib == ia || !(damaged_[ia] || damaged_[ib])
                                      : !betweenBodies_) ||
                            cell_[ib] != c)
                            continue;
                        // A pair of one body that was a's neighbour: its bond, if intact, holds
                        // the pair; if broken, the pair's separation caps its contact distance.
                        const Index bond = sameBody ? pairOf(a, static_cast<Index>(ib)) : -1;
                        if (bond >= 0 && bondIntact[static_cast<std::size_t>(bond)]) continue;
                        const Vec3 d = x[ia] - x[ib];
                        const double r2 = d.squaredNorm();
                        const double reach = shape.largestRadius[ia] + shape.largestRadius[ib];
                        if (!(r2 < reach * reach) || r2 == 0.0) continue;
                        const double r = std::sqrt(r2);
                        const Vec3 n = d / r;
                        const Vec3 ua = shape.S[ia] * n, ub = shape.S[ib] * n;
                        const double na = ua.norm(), nb = ub.norm();
                        double contactDistance = 1.0 / na + 1.0 / nb;  // d_ab(n)
                        // A broken bond: no farther than the largest distance the pair has had
                        // since it broke (this one included; recordSeparations caps it at the
                        // reference distance), so that a bond that breaks in compressed material
                        // stores no energy and a crack's faces at rest touch without force.
                        double apart = contactDistance;
                        if (bond >= 0)
                            apart = separation.empty()
                                        ? r
                                        : std::max(separation[static_cast<std::size_t>(bond)], r);
                        const bool ellipsoids = contactDistance <= apart;
                        contactDistance = std::min(contactDistance, apart);
                        const double gap = contactDistance - r;
                        if (!(gap > 0.0)) continue;
                        // h = −∂d_ab/∂n: the tangential part turns the force towards the
                        // ellipsoids' normals, so that f = −∂U/∂x_a exactly (0 when the
                        // reference distance is the contact distance).
                        const Vec3 h = ellipsoids
                                           ? Vec3(shape.S[ia].transpose() * ua / (na * na * na) +
                                                  shape.S[ib].transpose() * ub / (nb * nb * nb))
                                           : Vec3::Zero();
                        const double kb = stiffness_[ib];
                        const double kab = ka * kb / (ka + kb);        // springs in series
                        const Vec3 grad = n + (h - n.dot(h) * n) / r;  // −∂gap/∂x_a
                        const Vec3 fab = (kab * gap) * grad;
                        f += fab;
                        if (!sameBody)
                            byBody[rangeOfBody_[static_cast<std::size_t>(ref.body[ib])]] += fab;
                        u += 0.25 * kab * gap * gap;  // half of the pair's ½ k gap²
                        // The spring's stiffness along −∂gap/∂x_a is k |∂gap/∂x_a|² (> k where
                        // the ellipsoids meet obliquely).
                        w2 += kab * grad.squaredNorm() *
                              (1.0 / ma + 1.0 / std::sqrt(ma * ref.mass[ib]));
                        ++count;
                    }
                }
        force[ia] += f;
        frequency2[ia] += w2;
        energy_[ia] = u;
        pairCount_[ia] = count;
    });
    long counted = 0;
    for (Index a = owned_.begin; a < owned_.end; ++a)
        counted += pairCount_[static_cast<std::size_t>(a)];
    pairs_ = counted / 2;
    const ExactSum energy =
        exactSum(owned_, [&](Index a) { return energy_[static_cast<std::size_t>(a)]; });
    return domain_ ? domain_->total(energy) : energy.value();
}

void PenaltyContact::bodyPairForces(std::vector<Vec3>& out) const {
    if (!betweenBodies_) {
        out.clear();
        return;
    }
    const std::size_t bodies = ranges_.size();
    out.assign(bodies * bodies, Vec3::Zero());
    std::vector<ExactSum>& sums = bodyPairScratch_;
    sums.assign(3 * bodies * bodies, ExactSum{});
    for (std::size_t i = 0; i < bodies; ++i) {
        const ParticleRange mine = owned_.within(ranges_[i].first, ranges_[i].second);
        for (Index a = mine.begin; a < mine.end; ++a) {
            const auto ia = static_cast<std::size_t>(a);
            if (!candidate_[ia]) continue;
            for (std::size_t j = 0; j < bodies; ++j)
                for (std::size_t r = 0; r < 3; ++r)
                    sums[3 * (i * bodies + j) + r].add(
                        forceByBody_[ia * bodies + j][static_cast<Index>(r)]);
        }
    }
    if (domain_) domain_->sum(sums);
    for (std::size_t k = 0; k < bodies * bodies; ++k)
        for (std::size_t r = 0; r < 3; ++r) out[k][static_cast<Index>(r)] = sums[3 * k + r].value();
}

}  // namespace gsph
