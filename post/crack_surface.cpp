// SPDX-License-Identifier: MIT
// The only translation unit that includes CGAL (compile cost: shared/toolchain.md).
#include "crack_surface.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph::post {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<Index, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Point = Kernel::Point_3;

// Ghosts may not come closer than this fraction of d_a to a particle or to each other.
constexpr double kGhostExclusion = 0.5;
// Neighbours up to this multiple of the nearest-neighbour distance are mirrored.
constexpr double kMirrorReach = 1.25;
// Circumcentres closer than this fraction of the smallest spacing are one Voronoi vertex.
constexpr double kMergeTolerance = 1e-7;
// A facet vertex farther than this multiple of |X_b − X_a| from the midpoint: a sliver's
// circumcentre, not a cell's boundary.
constexpr double kFarVertex = 2.0;
// Facets below this fraction of |X_b − X_a|² are the zero-area duals of cospherical cells.
constexpr double kDegenerateArea = 1e-12;

Vec3 toVec(const Point& p) {
    return Vec3(p.x(), p.y(), p.z());
}

// Vector area ½ Σ (p_i − p_0) × (p_{i+1} − p_0) of a closed polygon.
Vec3 vectorArea(const std::vector<Vec3>& p) {
    Vec3 s = Vec3::Zero();
    for (std::size_t i = 1; i + 1 < p.size(); ++i) s += (p[i] - p[0]).cross(p[i + 1] - p[0]);
    return 0.5 * s;
}

// Ghost points outside the boundary (header comment): mirrors of the near neighbours.
// `handle[i]`: the vertex of particle members[i].
void ghostPoints(const Delaunay& dt, const std::vector<Delaunay::Vertex_handle>& handle,
                 const std::vector<Vec3>& X, const std::vector<Index>& members,
                 std::vector<Index>& source, std::vector<Vec3>& position) {
    std::vector<Delaunay::Vertex_handle> adjacent;
    std::vector<Vec3> mine;
    for (std::size_t i = 0; i < members.size(); ++i) {
        const auto a = static_cast<std::size_t>(members[i]);
        if (handle[i] == Delaunay::Vertex_handle() ||
            static_cast<std::size_t>(handle[i]->info()) != a)
            continue;  // a duplicate point: its twin stands for it
        adjacent.clear();
        dt.finite_adjacent_vertices(handle[i], std::back_inserter(adjacent));
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& v : adjacent)
            nearest = std::min(nearest, (toVec(v->point()) - X[a]).norm());
        mine.clear();
        for (const auto& b : adjacent) {
            const Vec3 Xb = toVec(b->point());
            if ((Xb - X[a]).norm() > kMirrorReach * nearest) continue;
            const Vec3 g = 2.0 * X[a] - Xb;
            const double exclusion = kGhostExclusion * nearest;
            bool occupied = false;
            for (const auto& c : adjacent)
                occupied = occupied || (toVec(c->point()) - g).norm() < exclusion;
            for (const Vec3& m : mine) occupied = occupied || (m - g).norm() < exclusion;
            if (occupied) continue;
            mine.push_back(g);
            source.push_back(static_cast<Index>(a));
            position.push_back(g);
        }
    }
}

// Facets within this multiple of the largest facet size (√area) form the patch whose centroids
// give the local crack plane.
constexpr double kPatchRadius = 3.0;

// Per polygon, its reference area projected on the local crack plane (header comment); a
// patch holds the facets of the polygon's own body (`body`: per polygon) only.
std::vector<double> projectedAreas(const std::vector<Vec3>& ref, const CrackSurface& c,
                                   const std::vector<Index>& body) {
    const std::size_t m = c.polygons();
    std::vector<Index> bodies = body;
    std::sort(bodies.begin(), bodies.end());
    bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
    std::vector<std::int64_t> group(m);  // position of the polygon's body in `bodies`
    for (std::size_t p = 0; p < m; ++p)
        group[p] = std::lower_bound(bodies.begin(), bodies.end(), body[p]) - bodies.begin();
    std::vector<Vec3> centroid(m), normal(m);
    std::vector<double> size(bodies.size(), 0.0);  // per body, its largest facet's √area
    for (std::size_t p = 0; p < m; ++p) {
        std::vector<Vec3> corners;
        for (Index k = c.offsets[p]; k < c.offsets[p + 1]; ++k)
            corners.push_back(
                ref[static_cast<std::size_t>(c.connectivity[static_cast<std::size_t>(k)])]);
        Vec3 sum = Vec3::Zero();
        for (const Vec3& q : corners) sum += q;
        centroid[p] = sum / static_cast<double>(corners.size());
        normal[p] = vectorArea(corners).normalized();
        double& largest = size[static_cast<std::size_t>(group[p])];
        largest = std::max(largest, std::sqrt(c.referenceArea[p]));
    }
    // Per body, a uniform grid of cell R over the centroids: the patch of p is in the 27 cells
    // around it. Keys: (body, cell).
    using Key = std::array<std::int64_t, 4>;
    auto keyOf = [&](std::size_t p) {
        const std::int64_t g = group[p];
        const double R = kPatchRadius * size[static_cast<std::size_t>(g)];
        const Vec3& x = centroid[p];
        return Key{g, static_cast<std::int64_t>(std::floor(x[0] / R)),
                   static_cast<std::int64_t>(std::floor(x[1] / R)),
                   static_cast<std::int64_t>(std::floor(x[2] / R))};
    };
    std::vector<std::pair<Key, std::size_t>> grid(m);
    for (std::size_t p = 0; p < m; ++p) grid[p] = {keyOf(p), p};
    std::sort(grid.begin(), grid.end());
    std::vector<double> out(m);
    parallelFor(static_cast<std::ptrdiff_t>(m), [&](std::ptrdiff_t pi) {
        const auto p = static_cast<std::size_t>(pi);
        const Key home = keyOf(p);
        const double R = kPatchRadius * size[static_cast<std::size_t>(group[p])];
        double weight = 0.0;
        Vec3 first = Vec3::Zero();
        Mat3 second = Mat3::Zero();
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const Key k = {home[0], home[1] + dx, home[2] + dy, home[3] + dz};
                    auto it = std::lower_bound(grid.begin(), grid.end(),
                                               std::make_pair(k, std::size_t{0}));
                    for (; it != grid.end() && it->first == k; ++it) {
                        const std::size_t q = it->second;
                        const Vec3 d = centroid[q] - centroid[p];
                        if (d.norm() > R) continue;
                        const double A = c.referenceArea[q];
                        weight += A;
                        first += A * d;
                        second += A * d * d.transpose();
                    }
                }
        const Vec3 mean = first / weight;
        const Mat3 covariance = second / weight - mean * mean.transpose();
        const Eigen::SelfAdjointEigenSolver<Mat3> eigen(covariance);
        const Vec3 lambda = eigen.eigenvalues();  // ascending
        // A patch that does not span a plane (one facet, one row) keeps the facet's own area.
        const bool planar = lambda[1] > 1e-6 * lambda[2] && lambda[2] > 0.0;
        out[p] = planar ? c.referenceArea[p] * std::abs(normal[p].dot(eigen.eigenvectors().col(0)))
                        : c.referenceArea[p];
    });
    return out;
}

}  // namespace

double CrackSurface::totalProjectedArea() const {
    return std::accumulate(projectedArea.begin(), projectedArea.end(), 0.0);
}

double CrackSurface::totalReferenceArea() const {
    return std::accumulate(referenceArea.begin(), referenceArea.end(), 0.0);
}

// A Delaunay edge between two particles and its Voronoi facet.
struct CrackSurfaces::Facet {
    Index a, b;  ///< a < b
    double area;
    std::vector<Index> polygon;  ///< Voronoi vertices, in order
};

CrackSurfaces::CrackSurfaces(const std::vector<Vec3>& X, const std::vector<Index>& body)
    : particles_(X.size()), body_(body) {
    if (!body.empty() && body.size() != X.size())
        throw InputError("crack surfaces: " + std::to_string(body.size()) + " body ids for " +
                         std::to_string(X.size()) + " particles");
    // The particles of each body, in index order (one body if no ids are given).
    std::vector<std::pair<Index, Index>> byBody(X.size());
    for (std::size_t a = 0; a < X.size(); ++a)
        byBody[a] = {body.empty() ? 0 : body[a], static_cast<Index>(a)};
    std::sort(byBody.begin(), byBody.end());
    std::vector<Facet> found;
    std::vector<Index> members;
    std::size_t spanning = 0;
    for (std::size_t k = 0; k < byBody.size();) {
        members.clear();
        const Index id = byBody[k].first;
        for (; k < byBody.size() && byBody[k].first == id; ++k) members.push_back(byBody[k].second);
        if (triangulate(X, members, found))
            ++spanning;
        else
            ++flatBodies_;
    }
    if (spanning == 0) throw InputError("crack surfaces need particles that span three dimensions");
    std::sort(found.begin(), found.end(), [](const Facet& p, const Facet& q) {
        return std::tie(p.a, p.b) < std::tie(q.a, q.b);
    });
    rowBegin_.assign(X.size() + 1, 0);
    polygonBegin_.push_back(0);
    for (const Facet& f : found) {
        ++rowBegin_[static_cast<std::size_t>(f.a) + 1];
        facetPartner_.push_back(f.b);
        facetArea_.push_back(f.area);
        polygon_.insert(polygon_.end(), f.polygon.begin(), f.polygon.end());
        polygonBegin_.push_back(static_cast<Index>(polygon_.size()));
    }
    std::partial_sum(rowBegin_.begin(), rowBegin_.end(), rowBegin_.begin());
}

bool CrackSurfaces::triangulate(const std::vector<Vec3>& X, const std::vector<Index>& members,
                                std::vector<Facet>& found) {
    const auto n = static_cast<Index>(X.size());
    std::vector<std::pair<Point, Index>> points(members.size());
    for (std::size_t i = 0; i < members.size(); ++i) {
        const Vec3& p = X[static_cast<std::size_t>(members[i])];
        points[i] = {Point(p[0], p[1], p[2]), members[i]};
    }
    Delaunay dt(points.begin(), points.end());
    if (dt.dimension() < 3) return false;
    std::vector<Delaunay::Vertex_handle> handle(members.size());
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
        const auto i = std::lower_bound(members.begin(), members.end(), v->info());
        handle[static_cast<std::size_t>(i - members.begin())] = v;
    }

    // Ghosts are numbered after the particles and the other bodies' ghosts.
    const std::size_t firstGhost = ghostPosition_.size();
    ghostPoints(dt, handle, X, members, ghostSource_, ghostPosition_);
    std::vector<std::pair<Point, Index>> ghosts(ghostPosition_.size() - firstGhost);
    for (std::size_t g = 0; g < ghosts.size(); ++g) {
        const Vec3& p = ghostPosition_[firstGhost + g];
        ghosts[g] = {Point(p[0], p[1], p[2]), n + static_cast<Index>(firstGhost + g)};
    }
    dt.insert(ghosts.begin(), ghosts.end());

    // Reference position of every triangulation vertex (particles, then ghosts).
    auto vertexPosition = [&](Index k) {
        return k < n ? X[static_cast<std::size_t>(k)]
                     : ghostPosition_[static_cast<std::size_t>(k - n)];
    };
    // The particles' smallest spacing: the ghosts of two faces one spacing apart may nearly
    // coincide (4e-19 m apart, measured), and a quantum from them would merge every vertex.
    double minSpacing = std::numeric_limits<double>::infinity();
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
        if (e->first->vertex(e->second)->info() < n && e->first->vertex(e->third)->info() < n)
            minSpacing = std::min(minSpacing, (toVec(e->first->vertex(e->second)->point()) -
                                               toVec(e->first->vertex(e->third)->point()))
                                                  .norm());

    // Voronoi vertices: circumcentres of the finite cells, merged when they coincide (the
    // cells of one cospherical lattice cube share one), ordered by their rounded position.
    std::vector<Delaunay::Cell_handle> cells;
    cells.reserve(dt.number_of_finite_cells());
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) cells.push_back(c);
    std::vector<Vec3> centre(cells.size());
    std::vector<std::array<std::int64_t, 3>> key(cells.size());
    const double quantum = kMergeTolerance * minSpacing;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        centre[c] = toVec(dt.dual(cells[c]));
        for (int d = 0; d < 3; ++d)
            key[c][static_cast<std::size_t>(d)] =
                static_cast<std::int64_t>(std::llround(centre[c][d] / quantum));
    }
    std::vector<std::size_t> order(cells.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
        return std::tie(key[p], p) < std::tie(key[q], q);
    });
    for (std::size_t r = 0; r < order.size(); ++r) {
        const std::size_t c = order[r];
        if (r == 0 || key[c] != key[order[r - 1]]) {
            voronoiPosition_.push_back(centre[c]);
            std::array<Index, 4> corners{};
            for (int i = 0; i < 4; ++i)
                corners[static_cast<std::size_t>(i)] = cells[c]->vertex(i)->info();
            voronoiCell_.push_back(corners);
        }
        cells[c]->info() = static_cast<Index>(voronoiPosition_.size() - 1);
    }

    // Facets of the edges between two particles.
    std::vector<Vec3> corners;
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        Index a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
        if (a >= n || b >= n) continue;
        if (a > b) std::swap(a, b);
        Facet f{a, b, 0.0, {}};
        bool bounded = true;
        Delaunay::Cell_circulator c = dt.incident_cells(*e), done = c;
        do {
            if (dt.is_infinite(c)) {
                bounded = false;
                break;
            }
            const Index v = c->info();
            if (f.polygon.empty() || f.polygon.back() != v) f.polygon.push_back(v);
        } while (++c != done);
        if (!bounded) {
            ++droppedFacets_;
            continue;
        }
        if (f.polygon.size() > 1 && f.polygon.front() == f.polygon.back()) f.polygon.pop_back();
        if (f.polygon.size() < 3) continue;  // dual of a cospherical cell: no area
        const Vec3 Xa = vertexPosition(a), Xb = vertexPosition(b);
        const double length = (Xb - Xa).norm();
        const Vec3 middle = 0.5 * (Xa + Xb);
        // The circulator starts at a cell chosen by CGAL's memory layout: start from the smallest
        // Voronoi vertex instead, and turn about a → b (the facet's normal along the bond).
        std::rotate(f.polygon.begin(), std::min_element(f.polygon.begin(), f.polygon.end()),
                    f.polygon.end());
        const auto cornersOf = [&] {
            corners.clear();
            for (Index v : f.polygon)
                corners.push_back(voronoiPosition_[static_cast<std::size_t>(v)]);
        };
        cornersOf();
        if (vectorArea(corners).dot(Xb - Xa) < 0.0) {
            std::reverse(f.polygon.begin() + 1, f.polygon.end());
            cornersOf();
        }
        bool near = true;
        for (const Vec3& q : corners) near = near && (q - middle).norm() <= kFarVertex * length;
        f.area = vectorArea(corners).norm();
        if (f.area < kDegenerateArea * length * length) continue;
        if (!near) {
            ++droppedFacets_;
            continue;
        }
        found.push_back(std::move(f));
    }
    return true;
}

Index CrackSurfaces::facetOf(Index a, Index b) const {
    const auto first = facetPartner_.begin() + rowBegin_[static_cast<std::size_t>(a)];
    const auto last = facetPartner_.begin() + rowBegin_[static_cast<std::size_t>(a) + 1];
    const auto it = std::lower_bound(first, last, b);
    return it != last && *it == b ? static_cast<Index>(it - facetPartner_.begin()) : Index{-1};
}

CrackSurface CrackSurfaces::surface(const Snapshot& s) const {
    if (static_cast<std::size_t>(s.size()) != particles_)
        throw InputError("snapshot at t = " + std::to_string(s.state.time) + " has " +
                         std::to_string(s.size()) + " particles, the run's first has " +
                         std::to_string(particles_));
    const auto m = static_cast<std::ptrdiff_t>(s.brokenBonds.size());
    std::vector<Index> facet(s.brokenBonds.size());
    parallelFor(m, [&](std::ptrdiff_t k) {
        const auto& [a, b] = s.brokenBonds[static_cast<std::size_t>(k)];
        facet[static_cast<std::size_t>(k)] = facetOf(std::min(a, b), std::max(a, b));
    });
    CrackSurface out;
    std::vector<Index> pointOf(voronoiPosition_.size(), -1);
    std::vector<Index> used;  // Voronoi vertex of each output point
    for (std::size_t k = 0; k < facet.size(); ++k) {
        const Index f = facet[k];
        if (f < 0) {
            ++out.brokenBondsWithoutFacet;
            continue;
        }
        const auto fi = static_cast<std::size_t>(f);
        for (Index p = polygonBegin_[fi]; p < polygonBegin_[fi + 1]; ++p) {
            const auto v = static_cast<std::size_t>(polygon_[static_cast<std::size_t>(p)]);
            if (pointOf[v] < 0) {
                pointOf[v] = static_cast<Index>(used.size());
                used.push_back(static_cast<Index>(v));
            }
            out.connectivity.push_back(pointOf[v]);
        }
        out.offsets.push_back(static_cast<Index>(out.connectivity.size()));
        out.referenceArea.push_back(facetArea_[fi]);
        const auto& [a, b] = s.brokenBonds[k];
        out.bond.push_back({std::min(a, b), std::max(a, b)});
    }
    // Each Voronoi vertex moves with its cell's particles: x̄ + F̄ (c − p̄) (header comment).
    const auto n = static_cast<Index>(particles_);
    out.points.resize(used.size());
    parallelFor(static_cast<std::ptrdiff_t>(used.size()), [&](std::ptrdiff_t i) {
        const auto v = static_cast<std::size_t>(used[static_cast<std::size_t>(i)]);
        Vec3 xMean = Vec3::Zero(), pMean = Vec3::Zero();
        Mat3 FMean = Mat3::Zero();
        for (Index k : voronoiCell_[v]) {
            const bool ghost = k >= n;
            const auto a =
                static_cast<std::size_t>(ghost ? ghostSource_[static_cast<std::size_t>(k - n)] : k);
            const Vec3 p = ghost ? ghostPosition_[static_cast<std::size_t>(k - n)] : s.X[a];
            xMean += s.state.x[a] + s.state.F[a] * (p - s.X[a]);
            pMean += p;
            FMean += s.state.F[a];
        }
        out.points[static_cast<std::size_t>(i)] =
            0.25 * xMean + 0.25 * FMean * (voronoiPosition_[v] - 0.25 * pMean);
    });
    std::vector<Vec3> reference(used.size());
    for (std::size_t i = 0; i < used.size(); ++i)
        reference[i] = voronoiPosition_[static_cast<std::size_t>(used[i])];
    std::vector<Index> polygonBody(out.polygons(), 0);
    if (!body_.empty())
        for (std::size_t p = 0; p < out.polygons(); ++p)
            polygonBody[p] = body_[static_cast<std::size_t>(out.bond[p][0])];
    out.projectedArea = projectedAreas(reference, out, polygonBody);
    return out;
}

}  // namespace gsph::post
