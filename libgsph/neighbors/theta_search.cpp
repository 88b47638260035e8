// SPDX-License-Identifier: MIT
#include "neighbors/theta_search.hpp"

#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "kernel/cubic_bspline.hpp"

namespace gsph {
namespace {

// Pairs at exactly q = 2 have W = ∇W = 0; the tolerance keeps them out whatever the round-off.
constexpr double kSupportTolerance = 1e-10;
// θ-offsets within this fraction of Δθ of an integer vector are lattice offsets.
constexpr double kLatticeTolerance = 1e-6;

struct SpaceSearch {
    const LatticeSpace* lattice = nullptr;
    double radius2 = 0.0;  // (2h)², shrunk by kSupportTolerance
    Vec3 period = Vec3::Zero();
    int stencilHalfWidth = 0;  // m: lattice offsets lie in [−m, m]^3
    Index tableStart = 0;      // first kernel-table entry of this space
};

// A point of a space's search: a particle at home (points 0 … n−1 are the particles
// themselves) or a transient particle's coordinates in another space (DESIGN §6).
struct SearchPoint {
    Index owner = 0;
    Index space = 0;
    Vec3 theta = Vec3::Zero();
    double omega = 0.0;  // θ-volume of a transient point (0 at home: the space's Δθ^d)
};

std::vector<SearchPoint> searchPoints(const Reference& ref) {
    std::vector<SearchPoint> points(ref.X.size() + ref.overset.size());
    for (std::size_t a = 0; a < ref.X.size(); ++a)
        points[a] = {static_cast<Index>(a), ref.space[a], ref.theta[a], 0.0};
    for (std::size_t e = 0; e < ref.overset.size(); ++e) {
        const OversetEntry& o = ref.overset[e];
        points[ref.X.size() + e] = {o.particle, o.space, o.theta, o.omega};
    }
    return points;
}

Vec3 minimumImage(Vec3 r, const SpaceSearch& s) {
    for (int d = 0; d < 3; ++d)
        if (s.lattice->periodic[d]) r[d] -= s.period[d] * std::floor(r[d] / s.period[d] + 0.5);
    return r;
}

Index latticeKernelId(const Vec3& r, const SpaceSearch& s) {
    const int m = s.stencilHalfWidth;
    const int w = 2 * m + 1;
    Index id = 0;
    for (int d = 0; d < 3; ++d) {
        const double o = r[d] / s.lattice->dtheta;
        const double k = std::floor(o + 0.5);
        if (std::abs(o - k) > kLatticeTolerance || std::abs(k) > m) return -1;
        id = id * w + static_cast<Index>(k) + m;
    }
    return s.tableStart + id;
}

KernelEntry kernelEntry(const CubicBSpline& kernel, double omega, const Vec3& r) {
    KernelEntry e;
    const double d = r.norm();
    e.gradW = omega * kernel.gradient(r);
    e.W = omega * kernel.value(d);
    e.thetaOffset = r;
    return e;
}

std::vector<SpaceSearch> prepareSpaces(Reference& ref) {
    if (ref.spaces.empty()) throw InputError("reference has no generalized space");
    std::vector<SpaceSearch> out(ref.spaces.size());
    ref.pairs.table.clear();
    for (std::size_t s = 0; s < ref.spaces.size(); ++s) {
        const LatticeSpace& L = ref.spaces[s];
        if (!(L.dtheta > 0.0)) throw InputError("space " + std::to_string(s) + ": Δθ must be > 0");
        const CubicBSpline kernel(ref.dim.value, ref.kappa * L.dtheta);
        SpaceSearch& S = out[s];
        S.lattice = &L;
        const double R = kernel.supportRadius();
        S.radius2 = R * R * (1.0 - kSupportTolerance);
        for (int d = 0; d < 3; ++d) S.period[d] = L.cells[static_cast<std::size_t>(d)] * L.dtheta;
        S.stencilHalfWidth = static_cast<int>(std::ceil(2.0 * ref.kappa));
        S.tableStart = static_cast<Index>(ref.pairs.table.size());
        const int m = S.stencilHalfWidth;
        for (int i = -m; i <= m; ++i)
            for (int j = -m; j <= m; ++j)
                for (int k = -m; k <= m; ++k)
                    ref.pairs.table.push_back(
                        kernelEntry(kernel, thetaVolume(ref.dim, L), Vec3(i, j, k) * L.dtheta));
    }
    return out;
}

// Calls visit(p, r) for every search point p in particle a's home space within the support
// (r = θ_a − θ_p, minimum image); implemented by the two search structures below.
class CellList {
  public:
    // On a space whose particles all sit on lattice sites, the cells are the lattice cells
    // (at most one particle each) and the visited cells are the sites within the support: no
    // wasted distance checks. Otherwise cells of one support radius and their 27 neighbours.
    CellList(const Reference& ref, const std::vector<SpaceSearch>& spaces,
             const std::vector<SearchPoint>& points)
        : ref_(ref), points_(points) {
        grids_.resize(spaces.size());
        std::vector<bool> onLattice(spaces.size(), true);
        for (const SearchPoint& p : points) {
            const auto s = static_cast<std::size_t>(p.space);
            const Vec3 t = p.theta / spaces[s].lattice->dtheta;
            for (int d = 0; d < ref.dim.value; ++d) {
                const double i = t[d] - 0.5;
                if (std::abs(i - std::floor(i + 0.5)) > kLatticeTolerance || i < -0.5 ||
                    i > spaces[s].lattice->cells[static_cast<std::size_t>(d)] - 0.5)
                    onLattice[s] = false;
            }
        }
        // The grid never has more cells than a few per point (64-bit products): a lattice
        // extent that disagrees with the particle count (a damaged or crafted file) falls back
        // to support-sized cells, and those are coarsened until the bound holds.
        std::vector<std::int64_t> pointsIn(spaces.size(), 0);
        for (const SearchPoint& p : points) ++pointsIn[static_cast<std::size_t>(p.space)];
        const auto cellBound = [&](std::size_t s) { return 4 * pointsIn[s] + 64; };
        for (std::size_t s = 0; s < spaces.size(); ++s) {
            std::int64_t product = 1;
            for (int d = 0; d < 3; ++d)
                product *= std::max<std::int64_t>(
                    1, spaces[s].lattice->cells[static_cast<std::size_t>(d)]);
            if (product > cellBound(s)) onLattice[s] = false;
        }
        for (std::size_t s = 0; s < spaces.size(); ++s) {
            Grid& g = grids_[s];
            g.search = &spaces[s];
            const double R = std::sqrt(spaces[s].radius2 / (1.0 - kSupportTolerance));
            const int zDim = ref.dim.value == 2 ? 0 : 1;
            for (int d = 0; d < 3; ++d) {
                g.lo[d] = 0.0;
                const double extent = std::max(spaces[s].period[d], R);
                g.n[d] = onLattice[s]
                             ? spaces[s].lattice->cells[static_cast<std::size_t>(d)]
                             : static_cast<int>(std::clamp(std::floor(extent / R), 1.0, 1e9));
                g.cellSize[d] = onLattice[s] ? spaces[s].lattice->dtheta : extent / g.n[d];
            }
            while (static_cast<std::int64_t>(g.n[0]) * g.n[1] * g.n[2] > cellBound(s)) {
                const int d = static_cast<int>(std::max_element(g.n, g.n + 3) - g.n);
                g.n[d] = std::max(1, g.n[d] / 2);
                g.cellSize[d] = std::max(spaces[s].period[d], R) / g.n[d];
            }
            const int m = onLattice[s] ? spaces[s].stencilHalfWidth : 1;
            for (int i = -m; i <= m; ++i)
                for (int j = -m; j <= m; ++j)
                    for (int k = -m * zDim; k <= m * zDim; ++k) {
                        const double r2 = (i * i + j * j + k * k) * g.cellSize[0] * g.cellSize[0];
                        if (!onLattice[s] || r2 < spaces[s].radius2) g.stencil.push_back({i, j, k});
                    }
            // Wrapping can map two stencil cells onto one only when a periodic index has fewer
            // cells than the stencil is wide.
            for (int d = 0; d < 3; ++d)
                g.mayAlias = g.mayAlias || (spaces[s].lattice->periodic[d] && g.n[d] < 2 * m + 1);
        }
        // θ may lie off the lattice box (a transient point past a block's boundary): it joins
        // the nearest boundary cell.
        const auto n = static_cast<Index>(points.size());
        cellOf_.resize(points.size());
        for (std::size_t p = 0; p < points.size(); ++p)
            cellOf_[p] =
                grids_[static_cast<std::size_t>(points[p].space)].cellIndex(points[p].theta);
        for (Grid& g : grids_) g.start.assign(static_cast<std::size_t>(g.cells()) + 1, 0);
        for (Index a = 0; a < n; ++a)
            ++grids_[static_cast<std::size_t>(points[static_cast<std::size_t>(a)].space)]
                  .start[static_cast<std::size_t>(cellOf_[static_cast<std::size_t>(a)]) + 1];
        for (Grid& g : grids_) {
            for (std::size_t c = 1; c < g.start.size(); ++c) g.start[c] += g.start[c - 1];
            g.members.resize(static_cast<std::size_t>(g.start.back()));
        }
        std::vector<std::vector<Index>> fill(grids_.size());
        for (std::size_t s = 0; s < grids_.size(); ++s)
            fill[s].assign(grids_[s].start.begin(), grids_[s].start.end() - 1);
        for (Index a = 0; a < n; ++a) {  // ascending a ⇒ each cell's members sorted
            const auto s = static_cast<std::size_t>(points[static_cast<std::size_t>(a)].space);
            const Index c = cellOf_[static_cast<std::size_t>(a)];
            grids_[s].members[static_cast<std::size_t>(fill[s][static_cast<std::size_t>(c)]++)] = a;
        }
    }

    template <class Visit>
    void forEachCandidate(Index a, Visit&& visit) const {
        const Grid& g = grids_[static_cast<std::size_t>(ref_.space[static_cast<std::size_t>(a)])];
        const Vec3& ta = ref_.theta[static_cast<std::size_t>(a)];
        int base[3];
        g.cellCoords(cellOf_[static_cast<std::size_t>(a)], base);
        thread_local std::vector<Index> seen;
        seen.clear();
        for (const std::array<int, 3>& o : g.stencil) {
            const int c[3] = {base[0] + o[0], base[1] + o[1], base[2] + o[2]};
            const Index cell = g.wrap(c);
            if (cell < 0) continue;
            if (g.mayAlias) {
                if (std::find(seen.begin(), seen.end(), cell) != seen.end()) continue;
                seen.push_back(cell);
            }
            for (Index k = g.start[static_cast<std::size_t>(cell)];
                 k < g.start[static_cast<std::size_t>(cell) + 1]; ++k) {
                const Index p = g.members[static_cast<std::size_t>(k)];
                const Vec3 r =
                    minimumImage(ta - points_[static_cast<std::size_t>(p)].theta, *g.search);
                if (r.squaredNorm() < g.search->radius2) visit(p, r);
            }
        }
    }

  private:
    struct Grid {
        const SpaceSearch* search = nullptr;
        double lo[3] = {0, 0, 0};
        double cellSize[3] = {1, 1, 1};
        int n[3] = {1, 1, 1};
        std::vector<std::array<int, 3>> stencil;  // cell offsets visited around a particle
        bool mayAlias = false;
        std::vector<Index> start, members;

        Index cells() const {
            return static_cast<Index>(static_cast<std::int64_t>(n[0]) * n[1] * n[2]);
        }
        Index cellIndex(const Vec3& t) const {
            int c[3];
            for (int d = 0; d < 3; ++d) {
                int i = static_cast<int>(std::floor((t[d] - lo[d]) / cellSize[d]));
                if (search->lattice->periodic[d]) i = ((i % n[d]) + n[d]) % n[d];
                c[d] = std::clamp(i, 0, n[d] - 1);
            }
            return (static_cast<Index>(c[0]) * n[1] + c[1]) * n[2] + c[2];
        }
        void cellCoords(Index cell, int c[3]) const {
            c[2] = cell % n[2];
            c[1] = (cell / n[2]) % n[1];
            c[0] = cell / (n[1] * n[2]);
        }
        Index wrap(const int c[3]) const {
            int w[3];
            for (int d = 0; d < 3; ++d) {
                w[d] = c[d];
                if (search->lattice->periodic[d])
                    w[d] = ((w[d] % n[d]) + n[d]) % n[d];
                else if (w[d] < 0 || w[d] >= n[d])
                    return -1;
            }
            return (static_cast<Index>(w[0]) * n[1] + w[1]) * n[2] + w[2];
        }
    };

    const Reference& ref_;
    const std::vector<SearchPoint>& points_;
    std::vector<Grid> grids_;
    std::vector<Index> cellOf_;
};

// nanoflann k-d tree per space; periodic indices are handled by adding image points of the
// particles within one support of either end.
class KdTreeSearch {
  public:
    KdTreeSearch(const Reference& ref, const std::vector<SpaceSearch>& spaces,
                 const std::vector<SearchPoint>& points)
        : ref_(ref) {
        trees_.resize(spaces.size());
        for (std::size_t s = 0; s < spaces.size(); ++s) trees_[s].search = &spaces[s];
        for (std::size_t p = 0; p < points.size(); ++p)
            addWithImages(trees_[static_cast<std::size_t>(points[p].space)], static_cast<Index>(p),
                          points[p].theta, 0);
        for (Tree& t : trees_) {
            t.index =
                std::make_unique<Index3>(3, t.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
            t.index->buildIndex();
        }
    }

    template <class Visit>
    void forEachCandidate(Index a, Visit&& visit) const {
        const Tree& t = trees_[static_cast<std::size_t>(ref_.space[static_cast<std::size_t>(a)])];
        const Vec3& ta = ref_.theta[static_cast<std::size_t>(a)];
        std::vector<std::pair<std::uint32_t, double>> found;
        t.index->radiusSearch(ta.data(), t.search->radius2, found,
                              nanoflann::SearchParams(32, 0.0f, false));
        for (const auto& [k, d2] : found) {
            const Index b = t.cloud.owner[k];
            visit(b, ta - t.cloud.points[k]);
        }
    }

  private:
    struct Cloud {
        std::vector<Vec3> points;
        std::vector<Index> owner;
        std::size_t kdtree_get_point_count() const { return points.size(); }
        double kdtree_get_pt(std::size_t i, std::size_t d) const {
            return points[i][static_cast<int>(d)];
        }
        template <class Box>
        bool kdtree_get_bbox(Box&) const {
            return false;
        }
    };
    using Index3 =
        nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;
    struct Tree {
        const SpaceSearch* search = nullptr;
        Cloud cloud;
        std::unique_ptr<Index3> index;
    };

    void addWithImages(Tree& t, Index a, const Vec3& p, int fromDim) {
        t.cloud.points.push_back(p);
        t.cloud.owner.push_back(a);
        const double R = std::sqrt(t.search->radius2);
        for (int d = fromDim; d < 3; ++d) {
            if (!t.search->lattice->periodic[d]) continue;
            const double L = t.search->period[d];
            Vec3 img = p;
            if (p[d] < R)
                img[d] += L;
            else if (p[d] > L - R)
                img[d] -= L;
            else
                continue;
            addWithImages(t, a, img, d + 1);
        }
    }

    const Reference& ref_;
    std::vector<Tree> trees_;
};

template <class Search>
void fillPairs(Reference& ref, const std::vector<SpaceSearch>& spaces,
               const std::vector<SearchPoint>& points, const Search& search) {
    const Index n = ref.size();
    PairList& P = ref.pairs;
    std::vector<Index> count(static_cast<std::size_t>(n), 0);
    auto joins = [&](Index a, Index p) {
        const Index b = points[static_cast<std::size_t>(p)].owner;
        return a != b &&
               ref.body[static_cast<std::size_t>(a)] == ref.body[static_cast<std::size_t>(b)];
    };
    parallelFor(n, [&](Index a) {
        Index c = 0;
        search.forEachCandidate(a, [&](Index p, const Vec3&) { c += joins(a, p) ? 1 : 0; });
        count[static_cast<std::size_t>(a)] = c;
    });
    P.offset.assign(static_cast<std::size_t>(n) + 1, 0);
    for (Index a = 0; a < n; ++a)
        P.offset[static_cast<std::size_t>(a) + 1] =
            P.offset[static_cast<std::size_t>(a)] + count[static_cast<std::size_t>(a)];
    P.neighbor.resize(static_cast<std::size_t>(P.offset.back()));
    P.kernelId.resize(P.neighbor.size());
    // A neighbour joins a's list once: a transient point lives in another space than its
    // owner's home, so its owner is never also at home in a's space. Off-lattice pairs and
    // every transient pair (its ω is not the space's Δθ^d) are marked −1 − point for now.
    parallelFor(n, [&](Index a) {
        std::vector<std::pair<Index, Index>> local;
        local.reserve(static_cast<std::size_t>(count[static_cast<std::size_t>(a)]));
        const SpaceSearch& s =
            spaces[static_cast<std::size_t>(ref.space[static_cast<std::size_t>(a)])];
        search.forEachCandidate(a, [&](Index p, const Vec3& r) {
            if (!joins(a, p)) return;
            const Index id = p < n ? latticeKernelId(r, s) : -1;
            local.emplace_back(points[static_cast<std::size_t>(p)].owner, id >= 0 ? id : -1 - p);
        });
        std::sort(local.begin(), local.end());
        Index k = P.offset[static_cast<std::size_t>(a)];
        for (const auto& [b, id] : local) {
            P.neighbor[static_cast<std::size_t>(k)] = b;
            P.kernelId[static_cast<std::size_t>(k)] = id;
            ++k;
        }
    });
    // Off-lattice offsets and transient points each get their own table entry.
    for (Index a = 0; a < n; ++a)
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const Index id = P.kernelId[static_cast<std::size_t>(k)];
            if (id >= 0) continue;
            const SearchPoint& point = points[static_cast<std::size_t>(-1 - id)];
            const std::size_t s = static_cast<std::size_t>(ref.space[static_cast<std::size_t>(a)]);
            const Vec3 r =
                minimumImage(ref.theta[static_cast<std::size_t>(a)] - point.theta, spaces[s]);
            const CubicBSpline kernel(ref.dim.value, ref.kappa * ref.spaces[s].dtheta);
            const double omega =
                point.owner == -1 - id ? thetaVolume(ref.dim, ref.spaces[s]) : point.omega;
            P.kernelId[static_cast<std::size_t>(k)] = static_cast<Index>(P.table.size());
            P.table.push_back(kernelEntry(kernel, omega, r));
        }
}

void checkReference(const Reference& ref) {
    const std::size_t n = ref.X.size();
    if (n == 0) throw InputError("reference has no particles");
    if (ref.theta.size() != n || ref.body.size() != n || ref.space.size() != n)
        throw InputError("reference arrays X, theta, body, space differ in length");
    if (!(ref.kappa > 0.0)) throw InputError("kernel factor κ must be > 0");
    if (ref.dim.value != 2 && ref.dim.value != 3) throw InputError("dimension must be 2 or 3");
    for (std::size_t a = 0; a < n; ++a) {
        if (ref.space[a] < 0 || static_cast<std::size_t>(ref.space[a]) >= ref.spaces.size())
            throw InputError("particle " + std::to_string(a) + " has unknown space id " +
                             std::to_string(ref.space[a]));
        if (a > 0 && ref.body[a] < ref.body[a - 1])
            throw InputError("particles are not sorted by body (particle " + std::to_string(a) +
                             ")");
        if (ref.dim.value == 2 && ref.theta[a][2] != ref.theta[0][2])
            throw InputError("2-D reference with θ_z varying (particle " + std::to_string(a) + ")");
    }
    for (std::size_t e = 0; e < ref.overset.size(); ++e) {
        const OversetEntry& o = ref.overset[e];
        const std::string where = "overset entry " + std::to_string(e) + ": ";
        if (o.particle < 0 || static_cast<std::size_t>(o.particle) >= n)
            throw InputError(where + "particle " + std::to_string(o.particle) + " out of range");
        if (o.space < 0 || static_cast<std::size_t>(o.space) >= ref.spaces.size())
            throw InputError(where + "unknown space id " + std::to_string(o.space));
        if (o.space == ref.space[static_cast<std::size_t>(o.particle)])
            throw InputError(where + "particle " + std::to_string(o.particle) +
                             " is transient in its own home space");
        if (!o.theta.allFinite() || !(o.omega > 0.0) || !std::isfinite(o.omega))
            throw InputError(where + "θ must be finite and ω > 0");
        if (ref.dim.value == 2 && o.theta[2] != ref.theta[0][2])
            throw InputError(where + "2-D reference with θ_z varying");
    }
}

}  // namespace

void buildPairs(Reference& ref, SearchMethod method) {
    checkReference(ref);
    const std::vector<SpaceSearch> spaces = prepareSpaces(ref);
    const std::vector<SearchPoint> points = searchPoints(ref);
    if (method == SearchMethod::CellList)
        fillPairs(ref, spaces, points, CellList(ref, spaces, points));
    else
        fillPairs(ref, spaces, points, KdTreeSearch(ref, spaces, points));
}

}  // namespace gsph
