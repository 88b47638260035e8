// SPDX-License-Identifier: MIT
#include "conversion.hpp"

#include <algorithm>
#include <map>

#include "block_indexing.hpp"
#include "core/error.hpp"
#include "hex_geometry.hpp"
#include "hex_topology.hpp"
#include "space_gluing.hpp"

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
                    mesh.source + ": volume " + std::to_string(tag) +
                    " is in two physical volume groups, " +
                    groupLabel(mesh.volumeGroups[body].name, mesh.volumeGroups[body].tag) +
                    " and " + groupLabel(g.name, g.tag) + "; a volume belongs to one body");
            }
            body = static_cast<Index>(b);
        }
        if (!holdsHexes) {
            throw MeshError(mesh.source + ": physical volume " + groupLabel(g.name, g.tag) +
                            " holds no hexahedra");
        }
    }
    for (std::size_t v = 0; v < mesh.volumes.size(); ++v) {
        if (bodyOfVolume[v] < 0) {
            throw MeshError(mesh.source + ": volume " + std::to_string(mesh.volumes[v].tag) +
                            " is in no physical volume group; put every volume in exactly one "
                            "(each group is a body)");
        }
    }
    return bodyOfVolume;
}

/// Every hex must have a positive Jacobian at its corners in its own (gmsh) node order.
void checkElementOrientation(const HexMesh& mesh) {
    for (const HexVolume& v : mesh.volumes) {
        for (Index h = v.firstHex; h < v.firstHex + v.hexCount; ++h) {
            HexCorners x;
            for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[h][kGmshCorner[c]]];
            if (!(minCornerJacobian(x) > 0.0)) {
                throw MeshError(mesh.source + ": element " + std::to_string(mesh.hexTags[h]) +
                                " in volume " + std::to_string(v.tag) +
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
        const std::string name = g.name.empty() ? "surface_" + std::to_string(g.tag) : g.name;
        if (name.find('/') != std::string::npos || name == "." || name == "..") {
            throw MeshError(mesh.source + ": physical surface '" + name +
                            "' cannot name a particle set ('/' is not allowed)");
        }
        if (out.particles.sets.count(name) != 0) {
            throw MeshError(mesh.source + ": two physical surfaces are named '" + name + "'");
        }
        std::vector<Index>& members = out.particles.sets[name];
        for (const auto& quad : g.quads) {
            std::array<Index, 2> found{};
            const int n = adjacency.hexesWithFace(quad, -1, found);
            if (n == 0) {
                throw MeshError(mesh.source + ": physical surface '" + name +
                                "' has a quadrilateral that is not a face of any hexahedron");
            }
            for (int k = 0; k < std::min(n, 2); ++k) members.push_back(particleOfHex[found[k]]);
        }
        std::sort(members.begin(), members.end());
        members.erase(std::unique(members.begin(), members.end()), members.end());
        if (members.empty()) {
            out.warnings.push_back("particle set '" + name +
                                   "' is empty (its surfaces hold no "
                                   "quadrilaterals)");
        }
    }
}

/// Particles under construction: the output, and which hex went where.
struct Assembly {
    Conversion& out;
    std::vector<Index> particleOfHex;  // per hex
    std::vector<char> filled;          // per particle slot
};

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
                if (!(minCornerJacobian(x) > 0.0)) {
                    throw MeshError(mesh.source + ": element " + std::to_string(mesh.hexTags[h]) +
                                    " in volume " + std::to_string(block.volumeTag) +
                                    " is inverted (the structured grid folds there)");
                }
                const Int3 c = space.cellOf(entry, {i, j, k});
                const std::size_t a = first + c[0] +
                                      static_cast<std::size_t>(space.cells[0]) *
                                          (c[1] + static_cast<std::size_t>(space.cells[1]) * c[2]);
                if (as.filled[a]++ != 0) {
                    throw MeshError(mesh.source + ": internal error: two hexahedra at one cell");
                }
                pf.X[a] = hexCentre(x);
                pf.volume[a] = hexVolume(x);
                pf.theta[a] = Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5) * kDtheta;
                pf.latticeIndex[a] = {c[0], c[1], c[2]};
                pf.space[a] = spaceId;
                pf.body[a] = space.body;
                as.particleOfHex[h] = static_cast<Index>(a);
                as.out.elementOfParticle[a] = mesh.hexTags[h];
                const auto edges = edgeLengthRange(x);
                stats.minEdge = std::min(stats.minEdge, edges[0]);
                stats.maxEdge = std::max(stats.maxEdge, edges[1]);
            }
        }
    }
}

}  // namespace

Conversion convertHexMesh(const HexMesh& mesh) {
    if (mesh.hexes.empty()) {
        throw MeshError(mesh.source + ": the mesh has no hexahedra (nothing to convert)");
    }
    Conversion out;
    ParticleFile& pf = out.particles;
    const std::vector<Index> bodyOfVolume = assignBodies(mesh, pf.bodies);
    checkElementOrientation(mesh);

    const NodeHexAdjacency adjacency(static_cast<Index>(mesh.nodes.size()), mesh.hexes);
    std::vector<BlockLattice> blocks;
    blocks.reserve(mesh.volumes.size());
    for (const HexVolume& v : mesh.volumes) blocks.push_back(indexBlock(mesh, v, adjacency));
    const GluingResult glued = glueBlocks(blocks, bodyOfVolume);

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
    Assembly as{out, std::vector<Index>(n, -1), std::vector<char>(n, 0)};
    std::size_t offset = 0;  // spaces follow each other: sorted by body, then first volume
    for (std::size_t s = 0; s < glued.spaces.size(); ++s) {
        const GluedSpace& space = glued.spaces[s];
        pf.spaces.push_back(LatticeSpace{kDtheta, space.cells, space.periodic});
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
    buildSets(mesh, adjacency, as.particleOfHex, out);
    return out;
}

}  // namespace gsph::preproc
