// SPDX-License-Identifier: MIT
#include "conversion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "block_indexing.hpp"
#include "core/error.hpp"
#include "hex_geometry.hpp"
#include "hex_topology.hpp"
#include "space_gluing.hpp"
#include "space_map.hpp"
#include "uniform_lattice.hpp"

namespace gsph::preproc {

namespace {

std::string groupLabel(const std::string& name, int tag) {
    return name.empty() ? "(tag " + std::to_string(tag) + ")" : "'" + name + "'";
}

/// Body id of every volume (indexed like mesh.volumes) and the body list.
std::vector<Index> assignBodies(const HexMesh& mesh, std::vector<BodyInfo>& bodies) {
    std::vector<Index> bodyOfVolume(mesh.volumes.size(), -1);
    if (mesh.volumeGroups.empty()) {
        bodies = {BodyInfo{"", -1}};
        std::fill(bodyOfVolume.begin(), bodyOfVolume.end(), 0);
        return bodyOfVolume;
    }
    std::map<int, std::size_t> volumeIndex;
    for (std::size_t v = 0; v < mesh.volumes.size(); ++v) volumeIndex[mesh.volumes[v].tag] = v;
    for (std::size_t b = 0; b < mesh.volumeGroups.size(); ++b) {
        const VolumeGroup& g = mesh.volumeGroups[b];
        bodies.push_back({g.name, g.tag});
        bool holdsHexes = false;
        for (int tag : g.volumes) {
            const auto it = volumeIndex.find(tag);
            if (it == volumeIndex.end()) continue;
            holdsHexes = true;
            Index& body = bodyOfVolume[it->second];
            if (body >= 0 && body != static_cast<Index>(b)) {
                throw MeshError(
                    mesh.source + ": " + blockEntity(mesh) + " " + std::to_string(tag) +
                    " is in two physical " + blockEntity(mesh) + " groups, " +
                    groupLabel(mesh.volumeGroups[body].name, mesh.volumeGroups[body].tag) +
                    " and " + groupLabel(g.name, g.tag) + "; a " + blockEntity(mesh) +
                    " belongs to one body");
            }
            body = static_cast<Index>(b);
        }
        if (!holdsHexes) {
            throw MeshError(mesh.source + ": physical " + blockEntity(mesh) + " " +
                            groupLabel(g.name, g.tag) + " holds no " +
                            (mesh.dimension == 2 ? "quadrangles" : "hexahedra"));
        }
    }
    for (std::size_t v = 0; v < mesh.volumes.size(); ++v) {
        if (bodyOfVolume[v] < 0) {
            const std::string entity = blockEntity(mesh);
            throw MeshError(mesh.source + ": " + entity + " " +
                            std::to_string(mesh.volumes[v].tag) + " is in no physical " + entity +
                            " group; put every " + entity +
                            " in exactly one (each group is a body)");
        }
    }
    return bodyOfVolume;
}

std::string point(const Vec3& X) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", X[0], X[1], X[2]);
    return text;
}

/// A hex with an edge collapsed to a point: its block collapses onto a line or a point, as a
/// cylindrical index space does on its axis (DESIGN §6: cover the axis with a Cartesian core).
void checkCollapsedEdges(const HexMesh& mesh, const HexVolume& v, Index h, const HexCorners& x) {
    const auto edges = edgeLengthRange(x);
    for (int c = 0; c < 8; ++c) {
        for (int a = 0; a < 3; ++a) {
            const int d = c | (1 << a);
            if (d == c || (x[d] - x[c]).norm() > 1e-12 * edges[1]) continue;
            throw MeshError(mesh.source + ": element " + std::to_string(mesh.hexTags[h]) + " in " +
                            blockEntity(mesh) + " " + std::to_string(v.tag) +
                            " is degenerate: its edge at " + point(x[c]) +
                            " has zero length, so the block collapses onto a line or point "
                            "there, like a cylindrical space on its axis, where dX/dtheta is "
                            "singular; cover the axis with a Cartesian core block (an O-grid, "
                            "as in geometries/taylor_bar.geo)");
        }
    }
}

/// Every hex must have a positive Jacobian at its corners in its own (gmsh) node order.
void checkElementOrientation(const HexMesh& mesh) {
    for (const HexVolume& v : mesh.volumes) {
        for (Index h = v.firstHex; h < v.firstHex + v.hexCount; ++h) {
            HexCorners x;
            for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[h][kGmshCorner[c]]];
            if (!(minCornerJacobian(x) > 0.0)) {
                checkCollapsedEdges(mesh, v, h, x);  // a collapsed edge has its own message
                throw MeshError(mesh.source + ": element " + std::to_string(mesh.hexTags[h]) +
                                " in " + blockEntity(mesh) + " " + std::to_string(v.tag) + " at " +
                                point(hexCentre(x)) +
                                " is inverted or degenerate (its Jacobian is not positive at "
                                "every corner)");
            }
        }
    }
}

/// Particle sets from the physical surface groups.
void buildSets(const HexMesh& mesh, const NodeHexAdjacency& adjacency,
               const std::vector<Index>& particleOfHex, Conversion& out) {
    for (const SurfaceGroup& g : mesh.surfaceGroups) {
        const std::string name = particleSetName(mesh, g, out.particles);
        std::vector<std::pair<Index, Vec3>> pieces;
        for (const auto& quad : g.quads) {
            std::array<Index, 2> found{};
            const int n = adjacency.hexesWithFace(quad, -1, found);
            if (n == 0) {
                throw MeshError(mesh.source + ": physical " + setEntity(mesh) + " '" + name +
                                strayFaceFault(mesh));
            }
            for (int k = 0; k < std::min(n, 2); ++k) {
                const Index particle = particleOfHex[found[k]];
                if (particle < 0) continue;
                HexCorners x;
                for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[found[k]][kGmshCorner[c]]];
                pieces.emplace_back(
                    particle,
                    outwardQuadArea(mesh.nodes[quad[0]], mesh.nodes[quad[1]], mesh.nodes[quad[2]],
                                    mesh.nodes[quad[3]], hexCentre(x)));
            }
        }
        storeParticleSet(name, std::move(pieces), out);
    }
}

/// Particles under construction: the output, and which hex went where.
struct Assembly {
    Conversion& out;
    std::vector<Index> particleOfHex;  // per hex
    std::vector<char> filled;          // per particle slot
    std::vector<double> condition;     // per particle: cond(∂X/∂θ) at its centre
    std::vector<double> inPlane;       // the same without the one-layer axis (1 if none)
    std::vector<double> cornerRatio;   // smallest det ∂X/∂θ at a corner / det at the centre
    std::vector<Index> block;          // per particle: its block
    std::vector<Int3> blockCell;       // per particle: its cell in its block's frame
};

/// The index along which a space is one cell thick (a 2-D slab), or −1.
int oneLayerAxis(const Int3& cells) {
    int axis = -1, thin = 0;
    for (int d = 0; d < 3; ++d) {
        if (cells[d] == 1) {
            axis = d;
            ++thin;
        }
    }
    return thin == 1 ? axis : -1;
}

constexpr double kDtheta = 1.0;  // DESIGN §2: Δθ = 1 in every space

/// The particles of one block of a space: X at the hex's parametric centre, its exact volume,
/// θ = (i+½, j+½, k+½)·Δθ at its cell in the space, stored at `first` + its lattice-order rank.
void placeBlock(const HexMesh& mesh, const GluedSpace& space, std::size_t entry,
                const BlockLattice& block, Index spaceId, std::size_t first, Assembly& as) {
    ParticleFile& pf = as.out.particles;
    ConversionStats& stats = as.out.stats;
    for (int k = 0; k < block.cells[2]; ++k) {
        for (int j = 0; j < block.cells[1]; ++j) {
            for (int i = 0; i < block.cells[0]; ++i) {
                HexCorners x;
                for (int c = 0; c < 8; ++c) {
                    x[c] = mesh.nodes[block.node(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))];
                }
                const Index h = block.hex(i, j, k);
                const double cornerJacobian = minCornerJacobian(x);
                if (!(cornerJacobian > 0.0)) {
                    throw MeshError(mesh.source + ": element " + std::to_string(mesh.hexTags[h]) +
                                    " in " + blockEntity(mesh) + " " +
                                    std::to_string(block.volumeTag) + " at " + point(hexCentre(x)) +
                                    " is inverted (the structured grid folds there)");
                }
                const Int3 c = space.cellOf(entry, {i, j, k});
                const std::size_t a = first + c[0] +
                                      static_cast<std::size_t>(space.cells[0]) *
                                          (c[1] + static_cast<std::size_t>(space.cells[1]) * c[2]);
                if (as.filled[a]++ != 0) {
                    throw MeshError(mesh.source + ": internal error: two hexahedra at one cell");
                }
                // Condition of ∂X/∂θ at the centre (the block frame's columns are the
                // space's up to order and sign, which the singular values ignore).
                const Mat3 J = hexJacobian(x, Vec3::Zero());
                // A 2-D space's in-plane metric is what matters, whatever its in-plane cells.
                const int thin = mesh.dimension == 2 ? 2 : oneLayerAxis(space.cells);
                as.condition[a] = jacobianCondition(J);
                as.inPlane[a] =
                    thin < 0 ? 1.0 : jacobianCondition(J, space.toSpace[entry].R.perm[thin]);
                as.cornerRatio[a] = cornerJacobian / J.determinant();
                pf.X[a] = hexCentre(x);
                pf.volume[a] = hexVolume(x);
                pf.theta[a] = Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5) * kDtheta;
                pf.latticeIndex[a] = {c[0], c[1], c[2]};
                pf.space[a] = spaceId;
                pf.body[a] = space.body;
                as.particleOfHex[h] = static_cast<Index>(a);
                as.block[a] = space.blocks[entry];
                as.blockCell[a] = {i, j, k};
                as.out.elementOfParticle[a] = mesh.hexTags[h];
                const auto edges = edgeLengthRange(x, mesh.dimension == 2 ? depthAxis(x) : -1);
                stats.minEdge = std::min(stats.minEdge, edges[0]);
                stats.maxEdge = std::max(stats.maxEdge, edges[1]);
            }
        }
    }
}

/// Appends the reference positions of a space's lattice nodes (ParticleFile::nodes, lattice
/// order) from its blocks' mesh nodes; a node on a periodic seam is stored once.
void appendSpaceNodes(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                      const GluedSpace& space, const LatticeSpace& lattice,
                      std::vector<Vec3>& nodes) {
    const std::size_t first = nodes.size();
    const auto m = nodeExtent(lattice);
    nodes.resize(first + m[0] * m[1] * m[2],
                 Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
    for (std::size_t e = 0; e < space.blocks.size(); ++e) {
        const BlockLattice& block = blocks[static_cast<std::size_t>(space.blocks[e])];
        for (int k = 0; k <= block.cells[2]; ++k)
            for (int j = 0; j <= block.cells[1]; ++j)
                for (int i = 0; i <= block.cells[0]; ++i) {
                    const Int3 x = space.toSpace[e].node({i, j, k});
                    for (int d = 0; d < 3; ++d)
                        if (!space.periodic[d] && (x[d] < 0 || x[d] > space.cells[d]))
                            throw MeshError(mesh.source +
                                            ": internal error: a block node lies outside its "
                                            "space's lattice");
                    nodes[first + nodeRow(lattice, x[0], x[1], x[2])] =
                        mesh.nodes[static_cast<std::size_t>(block.node(i, j, k))];
                }
    }
    for (std::size_t r = first; r < nodes.size(); ++r)
        if (!nodes[r].allFinite())
            throw MeshError(mesh.source + ": internal error: a space's node lattice has a hole");
}

/// Drops the particles with keep = 0 from every per-particle array; renumbers particleOfHex
/// (−1 for a cut hex).
void compact(const std::vector<char>& keep, Assembly& as) {
    ParticleFile& pf = as.out.particles;
    std::vector<Index> newIndex(keep.size(), -1);
    Index kept = 0;
    for (std::size_t a = 0; a < keep.size(); ++a) {
        if (keep[a]) newIndex[a] = kept++;
    }
    auto squeeze = [&](auto& values) {
        std::size_t w = 0;
        for (std::size_t a = 0; a < keep.size(); ++a) {
            if (keep[a]) values[w++] = values[a];
        }
        values.resize(w);
    };
    squeeze(pf.X);
    squeeze(pf.theta);
    squeeze(pf.volume);
    squeeze(pf.space);
    squeeze(pf.body);
    squeeze(pf.latticeIndex);
    squeeze(as.out.elementOfParticle);
    squeeze(as.condition);
    squeeze(as.inPlane);
    squeeze(as.cornerRatio);
    squeeze(as.block);
    squeeze(as.blockCell);
    for (Index& p : as.particleOfHex) {
        if (p >= 0) p = newIndex[static_cast<std::size_t>(p)];
    }
}

/// DESIGN §6: in bodies of several spaces, cut holes where spaces overlap, then find the
/// transient particles. Every body gets its flags (all 0 in a body of one space).
void applyOverset(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                  const GluingResult& glued, const ConversionOptions& options, Assembly& as) {
    ParticleFile& pf = as.out.particles;
    ConversionStats& stats = as.out.stats;
    const SpaceRanking ranking =
        rankSpaces(mesh.source, mesh, blocks, glued, pf, options.priorities);
    std::vector<int> spacesOfBody(pf.bodies.size(), 0);
    for (const GluedSpace& s : glued.spaces) ++spacesOfBody[static_cast<std::size_t>(s.body)];
    SpaceMaps maps(glued.spaces.size());
    for (std::size_t s = 0; s < glued.spaces.size(); ++s) {
        if (spacesOfBody[static_cast<std::size_t>(glued.spaces[s].body)] < 2) continue;
        maps[s] =
            std::make_unique<SpaceMap>(mesh, blocks, glued.spaces[s], 2.0 * options.oversetKappa);
    }
    compact(cutHoles(mesh.source, pf, maps, ranking, stats.spaceVolumes, stats.cuts), as);
    stats.oversetKappa = options.oversetKappa;
    const ParticleOrigins origins{
        &glued, &blocks, as.block, as.blockCell, as.out.elementOfParticle, &stats.spaceVolumes};
    findTransients(mesh.source, pf, maps, origins, options.oversetKappa, options.transients,
                   stats.transients);
}

/// Worst condition number of ∂X/∂θ and smallest corner/centre Jacobian ratio per space; a
/// warning where either says the space is close to singular.
void reportMetric(const Assembly& as, Conversion& out) {
    const ParticleFile& pf = out.particles;
    out.stats.metric.assign(pf.spaces.size(), MetricReport{});
    for (std::size_t s = 0; s < pf.spaces.size(); ++s) {
        out.stats.metric[s].oneLayerAxis = pf.dimension == 2 ? 2 : oneLayerAxis(pf.spaces[s].cells);
    }
    for (Index a = 0; a < pf.size(); ++a) {
        MetricReport& m = out.stats.metric[static_cast<std::size_t>(pf.space[a])];
        const bool thin = m.oneLayerAxis >= 0;
        if ((thin ? as.inPlane[a] : as.condition[a]) > (thin ? m.inPlaneCondition : m.condition)) {
            m.worstParticle = a;
        }
        m.condition = std::max(m.condition, as.condition[a]);
        m.inPlaneCondition = std::max(m.inPlaneCondition, as.inPlane[a]);
        if (as.cornerRatio[a] < m.cornerRatio) {
            m.cornerRatio = as.cornerRatio[a];
            m.worstCornerParticle = a;
        }
    }
    const std::string advice =
        ": is the space close to a coordinate axis? Cover the axis with a Cartesian core block "
        "(an O-grid, as in geometries/taylor_bar.geo)";
    for (std::size_t s = 0; s < pf.spaces.size(); ++s) {
        const MetricReport& m = out.stats.metric[s];
        const double worst = m.oneLayerAxis < 0 ? m.condition : m.inPlaneCondition;
        char text[160];
        if (!(worst <= kIllConditioned)) {
            std::snprintf(text, sizeof text, "condition number %.3g > %g", worst, kIllConditioned);
            out.warnings.push_back("space " + std::to_string(s) +
                                   ": dX/dtheta is ill-conditioned (" + text + " at particle " +
                                   std::to_string(m.worstParticle) +
                                   ", X = " + point(pf.X[m.worstParticle]) + ")" + advice);
        }
        if (!(m.cornerRatio >= kCollapsingCell)) {
            std::snprintf(text, sizeof text, "det dX/dtheta at a corner is %.3g of its centre's",
                          m.cornerRatio);
            out.warnings.push_back("space " + std::to_string(s) + ": the cell of particle " +
                                   std::to_string(m.worstCornerParticle) +
                                   " (X = " + point(pf.X[m.worstCornerParticle]) +
                                   ") nearly collapses onto a line (" + text + ")" + advice);
        }
    }
}

/// In a 2-D mesh (quads extruded to unit depth along z) every space's third index must run
/// along the extrusion, towards +z: the 2-D file has its one cell along index 2. Block frames
/// follow x, y, z (block_indexing.hpp) and a space takes its first block's frame, so this holds
/// by construction; the check names the surface if it ever does not.
void checkExtrusionAxis(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                        const GluingResult& glued) {
    for (const GluedSpace& space : glued.spaces) {
        const BlockLattice& block = blocks[static_cast<std::size_t>(space.blocks[0])];
        const Vec3& origin = mesh.nodes[static_cast<std::size_t>(block.node(0, 0, 0))];
        const SignedPermutation& toSpace = space.toSpace[0].R;
        const int blockAxis = toSpace.perm[2];
        const Index far = block.node(blockAxis == 0, blockAxis == 1, blockAxis == 2);
        const Vec3 step = mesh.nodes[static_cast<std::size_t>(far)] - origin;
        if (block.cells[blockAxis] != 1 || step[0] != 0.0 || step[1] != 0.0 ||
            step[2] * toSpace.sign[2] != 1.0) {
            throw MeshError(mesh.source + ": internal error: surface " +
                            std::to_string(block.volumeTag) +
                            "'s space does not have the extrusion as its third index");
        }
    }
}

/// A 2-D mesh's conversion, done on the unit-depth slab, as a 2-D particle file: X_z = θ_z = 0
/// (particle and overset entries), set areas in the plane; volumes (the slab cells' volumes)
/// already are the areas per metre of depth, and the nodes the slab's two layers.
void flattenToPlane(const HexMesh& mesh, ParticleFile& pf) {
    for (const LatticeSpace& space : pf.spaces) {
        if (space.cells[2] != 1 || space.periodic[2]) {
            throw MeshError(mesh.source +
                            ": internal error: a 2-D space is not one cell along its third index");
        }
    }
    for (Vec3& X : pf.X) X[2] = 0.0;
    for (Vec3& theta : pf.theta) theta[2] = 0.0;
    for (Vec3& theta : pf.overset.theta) theta[2] = 0.0;
    for (auto& [name, areas] : pf.setAreas)
        for (Vec3& area : areas) area[2] = 0.0;
}
}  // namespace

void storeParticleSet(const std::string& name, std::vector<std::pair<Index, Vec3>> pieces,
                      Conversion& out) {
    std::sort(pieces.begin(), pieces.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Index>& members = out.particles.sets[name];
    std::vector<Vec3>& areas = out.particles.setAreas[name];
    for (const auto& [particle, area] : pieces) {
        if (members.empty() || members.back() != particle) {
            members.push_back(particle);
            areas.push_back(Vec3::Zero());
        }
        areas.back() += area;
    }
    if (members.empty()) {
        out.warnings.push_back("particle set '" + name +
                               "' is empty (its surfaces hold no quadrilaterals, or hole "
                               "cutting removed all its particles)");
    }
}

std::string particleSetName(const HexMesh& mesh, const SurfaceGroup& group,
                            const ParticleFile& particles) {
    std::string name = group.name;
    if (name.empty()) name = std::string(setEntity(mesh)) + '_' + std::to_string(group.tag);
    if (name.find('/') != std::string::npos || name == "." || name == "..") {
        throw MeshError(mesh.source + ": physical " + setEntity(mesh) + " '" + name +
                        "' cannot name a particle set ('/' is not allowed)");
    }
    if (particles.sets.count(name) != 0) {
        throw MeshError(mesh.source + ": two physical " + setEntity(mesh) + "s are named '" + name +
                        "'");
    }
    return name;
}

Conversion convertHexMesh(const HexMesh& mesh, const ConversionOptions& options) {
    if (mesh.hexes.empty()) {
        throw MeshError(mesh.source + ": the mesh has no hexahedra (nothing to convert)");
    }
    Conversion out;
    ParticleFile& pf = out.particles;
    pf.dimension = mesh.dimension;
    const std::vector<Index> bodyOfVolume = assignBodies(mesh, pf.bodies);
    checkElementOrientation(mesh);

    const NodeHexAdjacency adjacency(static_cast<Index>(mesh.nodes.size()), mesh.hexes);
    std::vector<BlockLattice> blocks;
    blocks.reserve(mesh.volumes.size());
    for (const HexVolume& v : mesh.volumes) blocks.push_back(indexBlock(mesh, v, adjacency));
    const GluingResult glued = glueBlocks(blocks, bodyOfVolume);
    if (mesh.dimension == 2) checkExtrusionAxis(mesh, blocks, glued);
    if (options.latticeSpacing != 0.0) {  // the uniform layout of standard SPH instead
        out.stats.minEdge = INFINITY;
        fillUniformLattice(mesh, blocks, glued, bodyOfVolume, adjacency, options.latticeSpacing,
                           out);
        if (options.onSpaces) options.onSpaces(out.particles, out.stats);
        if (mesh.dimension == 2) flattenToPlane(mesh, pf);
        return out;
    }

    const std::size_t n = mesh.hexes.size();
    pf.X.resize(n);
    pf.theta.resize(n);
    pf.volume.resize(n);
    pf.space.resize(n);
    pf.body.resize(n);
    pf.latticeIndex.resize(n);
    out.elementOfParticle.resize(n);
    out.stats.hexes = n;
    out.stats.minEdge = INFINITY;
    if (!(options.oversetKappa > 0.0 && options.oversetKappa <= kMaxOversetKappa)) {
        char text[96];
        std::snprintf(text, sizeof text, "the overset kappa must lie in (0, %g] (got %g)",
                      kMaxOversetKappa, options.oversetKappa);
        throw InputError(mesh.source + ": " + text);
    }
    Assembly as{out,
                std::vector<Index>(n, -1),
                std::vector<char>(n, 0),
                std::vector<double>(n),
                std::vector<double>(n),
                std::vector<double>(n),
                std::vector<Index>(n, -1),
                std::vector<Int3>(n)};
    std::size_t offset = 0;  // spaces follow each other: sorted by body, then first volume
    for (std::size_t s = 0; s < glued.spaces.size(); ++s) {
        const GluedSpace& space = glued.spaces[s];
        pf.spaces.push_back(LatticeSpace{kDtheta, space.cells, space.periodic});
        appendSpaceNodes(mesh, blocks, space, pf.spaces.back(), pf.nodes);
        out.stats.spaceVolumes.emplace_back();
        for (std::size_t e = 0; e < space.blocks.size(); ++e) {
            const BlockLattice& block = blocks[space.blocks[e]];
            out.stats.spaceVolumes.back().push_back(block.volumeTag);
            placeBlock(mesh, space, e, block, static_cast<Index>(s), offset, as);
        }
        offset += static_cast<std::size_t>(space.cells[0]) * space.cells[1] * space.cells[2];
    }
    if (offset != n || std::find(as.filled.begin(), as.filled.end(), 0) != as.filled.end()) {
        throw MeshError(mesh.source +
                        ": internal error: the spaces do not hold every hexahedron once");
    }
    out.stats.sharedFaces = glued.sharedFaces;
    out.stats.honouredFaces = glued.honouredFaces;
    out.stats.exhaustiveGluing = glued.exhaustive;
    if (!glued.exhaustive) {
        out.warnings.push_back("gluing blocks into spaces stopped after " +
                               std::to_string(kMaxSearchSteps) +
                               " search steps: the spaces are consistent but may not be the "
                               "fewest possible");
    }
    if (options.onSpaces) options.onSpaces(out.particles, out.stats);
    applyOverset(mesh, blocks, glued, options, as);
    buildSets(mesh, adjacency, as.particleOfHex, out);
    reportMetric(as, out);
    if (mesh.dimension == 2) flattenToPlane(mesh, pf);
    return out;
}

}  // namespace gsph::preproc
