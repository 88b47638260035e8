// SPDX-License-Identifier: MIT
#include "uniform_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "core/error.hpp"
#include "hex_geometry.hpp"
#include "space_map.hpp"

namespace gsph::preproc {

namespace {

/// The lattice of one body: its box, cells and which sites were kept.
struct BodyLattice {
    Vec3 origin = Vec3::Zero(), h = Vec3::Ones();
    Int3 cells = {0, 0, 0};
    std::vector<Index> particleOfSite;  ///< kept particle per site, −1 if cut; i fastest

    std::size_t site(const Int3& c) const {
        return static_cast<std::size_t>(c[0]) +
               static_cast<std::size_t>(cells[0]) *
                   (static_cast<std::size_t>(c[1]) + static_cast<std::size_t>(cells[1]) * c[2]);
    }
    Vec3 position(const Int3& c) const {
        return origin + Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5).cwiseProduct(h);
    }
    /// The cell holding X, clamped into the box.
    Int3 cellOf(const Vec3& X) const {
        Int3 c;
        for (int d = 0; d < 3; ++d) {
            const double u = std::floor((X[d] - origin[d]) / h[d]);
            c[d] = static_cast<int>(std::clamp(u, 0.0, static_cast<double>(cells[d] - 1)));
        }
        return c;
    }
};

/// The kept particle nearest X: its own cell's if kept, else the nearest in the cube of cells
/// of growing radius r around it (the staircase lies within a cell or two of the faces). A
/// particle found at radius r may be beaten by one at r + 1 (by less than a cell), never
/// farther out, so the search stops one radius after the first find.
Index nearestParticle(const BodyLattice& lat, const std::vector<Vec3>& X, const Vec3& point) {
    const Int3 c = lat.cellOf(point);
    if (const Index p = lat.particleOfSite[lat.site(c)]; p >= 0) return p;
    Index best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto scan = [&](int r) {
        for (int k = std::max(0, c[2] - r); k <= std::min(lat.cells[2] - 1, c[2] + r); ++k) {
            for (int j = std::max(0, c[1] - r); j <= std::min(lat.cells[1] - 1, c[1] + r); ++j) {
                for (int i = std::max(0, c[0] - r); i <= std::min(lat.cells[0] - 1, c[0] + r);
                     ++i) {
                    const Index p = lat.particleOfSite[lat.site({i, j, k})];
                    if (p < 0) continue;
                    const double d = (X[static_cast<std::size_t>(p)] - point).squaredNorm();
                    if (d < bestDistance || (d == bestDistance && p < best)) {
                        bestDistance = d;
                        best = p;
                    }
                }
            }
        }
    };
    const int reach = std::max({lat.cells[0], lat.cells[1], lat.cells[2]});
    for (int r = 1; r <= reach && best < 0; ++r) {
        scan(r);
        if (best >= 0) scan(r + 1);
    }
    return best;
}

void buildLatticeSets(const HexMesh& mesh, const NodeHexAdjacency& adjacency,
                      const std::vector<Index>& bodyOfHex, const std::vector<BodyLattice>& lattices,
                      Conversion& out) {
    ParticleFile& pf = out.particles;
    for (const SurfaceGroup& g : mesh.surfaceGroups) {
        const std::string name = particleSetName(mesh, g, pf);
        std::vector<std::pair<Index, Vec3>> pieces;
        for (const auto& quad : g.quads) {
            std::array<Index, 2> found{};
            if (adjacency.hexesWithFace(quad, -1, found) == 0) {
                throw MeshError(mesh.source + ": physical " + setEntity(mesh) + " '" + name +
                                strayFaceFault(mesh));
            }
            const Index hex = found[0];
            const BodyLattice& lat = lattices[static_cast<std::size_t>(bodyOfHex[hex])];
            HexCorners x;
            for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[hex][kGmshCorner[c]]];
            const Vec3 inside = hexCentre(x);
            // Bilinear face X(s,t) from its four nodes (gmsh order: a cycle).
            const Vec3& p0 = mesh.nodes[quad[0]];
            const Vec3& p1 = mesh.nodes[quad[1]];
            const Vec3& p2 = mesh.nodes[quad[2]];
            const Vec3& p3 = mesh.nodes[quad[3]];
            // A 2-D mesh's set quads are extruded segments (a, b, b', a'): sampled along the
            // segment only, since the slab is one cell deep.
            const bool plane = mesh.dimension == 2;
            const double hMin = plane ? std::min(lat.h[0], lat.h[1]) : lat.h.minCoeff();
            const double size = plane ? (p1 - p0).norm()
                                      : std::max({(p1 - p0).norm(), (p2 - p1).norm(),
                                                  (p3 - p2).norm(), (p0 - p3).norm()});
            const int samples = std::max(1, static_cast<int>(std::ceil(2.0 * size / hMin)));
            const int samplesAcross = plane ? 1 : samples;
            // Each sample point carries its share of the face's area to the particle it finds.
            const Vec3 share = outwardQuadArea(p0, p1, p2, p3, inside) / (samples * samplesAcross);
            for (int it = 0; it < samplesAcross; ++it) {
                for (int is = 0; is < samples; ++is) {
                    const double s = (is + 0.5) / samples, t = (it + 0.5) / samplesAcross;
                    const Vec3 onFace =
                        (1 - s) * (1 - t) * p0 + s * (1 - t) * p1 + s * t * p2 + (1 - s) * t * p3;
                    // Nudged into the face's hex: a face on a cell boundary picks the body side.
                    const Vec3 point = onFace + 1e-6 * (inside - onFace);
                    const Index p = nearestParticle(lat, pf.X, point);
                    if (p >= 0) pieces.emplace_back(p, share);
                }
            }
        }
        storeParticleSet(name, std::move(pieces), out);
    }
}

}  // namespace

void fillUniformLattice(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                        const GluingResult& glued, const std::vector<Index>& bodyOfVolume,
                        const NodeHexAdjacency& adjacency, double spacing, Conversion& out) {
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        char text[96];
        std::snprintf(text, sizeof text, "--lattice: the spacing must be positive (got %g)",
                      spacing);
        throw InputError(mesh.source + ": " + text);
    }
    ParticleFile& pf = out.particles;
    ConversionStats& stats = out.stats;
    const std::size_t bodies = pf.bodies.size();

    std::vector<Index> bodyOfHex(mesh.hexes.size(), 0);
    for (std::size_t v = 0; v < mesh.volumes.size(); ++v) {
        const HexVolume& vol = mesh.volumes[v];
        std::fill_n(bodyOfHex.begin() + vol.firstHex, vol.hexCount, bodyOfVolume[v]);
    }
    std::vector<std::vector<std::unique_ptr<SpaceMap>>> maps(bodies);
    std::vector<Eigen::AlignedBox3d> box(bodies);
    stats.lattice.assign(bodies, {});
    stats.spaceVolumes.assign(bodies, {});
    for (const GluedSpace& s : glued.spaces) {
        const auto b = static_cast<std::size_t>(s.body);
        maps[b].push_back(std::make_unique<SpaceMap>(mesh, blocks, s, 0.0));
        box[b].extend(maps[b].back()->bounds());
        for (Index e : s.blocks) stats.spaceVolumes[b].push_back(blocks[e].volumeTag);
    }
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        HexCorners x;
        for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[h][kGmshCorner[c]]];
        stats.lattice[static_cast<std::size_t>(bodyOfHex[h])].meshVolume += hexVolume(x);
        const auto edges = edgeLengthRange(x, mesh.dimension == 2 ? depthAxis(x) : -1);
        stats.minEdge = std::min(stats.minEdge, edges[0]);
        stats.maxEdge = std::max(stats.maxEdge, edges[1]);
    }

    std::vector<BodyLattice> lattices(bodies);
    for (std::size_t b = 0; b < bodies; ++b) {
        BodyLattice& lat = lattices[b];
        const Vec3 extent = box[b].sizes();
        double sites = 1.0;
        for (int d = 0; d < 3; ++d) {
            // A 2-D mesh's unit-depth slab keeps one cell along z.
            const bool slabDepth = d == 2 && mesh.dimension == 2;
            lat.cells[d] =
                slabDepth ? 1 : static_cast<int>(std::max(1.0, std::round(extent[d] / spacing)));
            lat.h[d] = extent[d] > 0.0 ? extent[d] / lat.cells[d] : spacing;
            sites *= lat.cells[d];
        }
        if (sites > kMaxLatticeSites) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "--lattice %g gives %.3g sites in body %zu's bounding box (at most %g)",
                          spacing, sites, b, kMaxLatticeSites);
            throw InputError(mesh.source + ": " + text);
        }
        lat.origin = box[b].min();
        lat.particleOfSite.assign(static_cast<std::size_t>(sites), -1);
        // Which sites lie in the body (SpaceMap queries are thread-safe).
        std::vector<char> keep(lat.particleOfSite.size(), 0);
        const auto siteCount = static_cast<std::ptrdiff_t>(keep.size());
#pragma omp parallel for schedule(dynamic, 256)
        for (std::ptrdiff_t n = 0; n < siteCount; ++n) {
            const auto un = static_cast<std::size_t>(n);
            const Int3 c = {static_cast<int>(un % lat.cells[0]),
                            static_cast<int>(un / lat.cells[0] % lat.cells[1]),
                            static_cast<int>(un / lat.cells[0] / lat.cells[1])};
            const Vec3 X = lat.position(c);
            for (const auto& map : maps[b]) {
                if (map->side(X) != SpaceMap::Side::Outside) {
                    keep[un] = 1;
                    break;
                }
            }
        }
        const auto spaceId = static_cast<Index>(b);
        pf.spaces.push_back(LatticeSpace{1.0, lat.cells, {false, false, false}});
        // The box lattice's corners (ParticleFile::nodes), lattice order.
        for (int k = 0; k <= lat.cells[2]; ++k)
            for (int j = 0; j <= lat.cells[1]; ++j)
                for (int i = 0; i <= lat.cells[0]; ++i)
                    pf.nodes.push_back(lat.origin + Vec3(i, j, k).cwiseProduct(lat.h));
        const double volume = lat.h[0] * lat.h[1] * lat.h[2];
        std::size_t kept = 0;
        for (std::size_t n = 0; n < keep.size(); ++n) {
            if (!keep[n]) continue;
            const Int3 c = {static_cast<int>(n % lat.cells[0]),
                            static_cast<int>(n / lat.cells[0] % lat.cells[1]),
                            static_cast<int>(n / lat.cells[0] / lat.cells[1])};
            lat.particleOfSite[n] = pf.size();
            pf.X.push_back(lat.position(c));
            pf.theta.push_back(Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5));
            pf.volume.push_back(volume);
            pf.space.push_back(spaceId);
            pf.body.push_back(spaceId);
            pf.latticeIndex.push_back({c[0], c[1], c[2]});
            ++kept;
        }
        if (kept == 0) {
            char text[160];
            std::snprintf(text, sizeof text,
                          ": --lattice %g keeps no particle of body %zu (the spacing is larger "
                          "than the body)",
                          spacing, b);
            throw MeshError(mesh.source + text);
        }
        stats.lattice[b].spacing = lat.h;
        stats.lattice[b].cells = lat.cells;
    }
    stats.hexes = mesh.hexes.size();
    stats.metric.assign(pf.spaces.size(), MetricReport{});  // ∂X/∂θ = diag(h): condition ≤ 1.01
    for (std::size_t s = 0; s < pf.spaces.size(); ++s) {
        const Vec3& h = stats.lattice[s].spacing;
        stats.metric[s].condition = h.maxCoeff() / h.minCoeff();
        stats.metric[s].inPlaneCondition = stats.metric[s].condition;
        if (mesh.dimension == 2) {  // the slab's unit depth is no spacing
            stats.metric[s].oneLayerAxis = 2;
            stats.metric[s].inPlaneCondition = h.head<2>().maxCoeff() / h.head<2>().minCoeff();
        }
    }
    buildLatticeSets(mesh, adjacency, bodyOfHex, lattices, out);
}

}  // namespace gsph::preproc
