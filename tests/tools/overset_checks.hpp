// SPDX-License-Identifier: MIT
// Checks of the overset data gsph-preproc writes (DESIGN §6): the spaces' isoparametric maps
// rebuilt from the mesh, and the transient entries checked against them.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "block_indexing.hpp"
#include "hex_topology.hpp"
#include "io/particle_file.hpp"
#include "space_gluing.hpp"
#include "space_map.hpp"

namespace gsph::test {

/// The isoparametric maps of the spaces of a one-body mesh, built as convertHexMesh builds them
/// (index the blocks, glue them, lay the nodes out in each space's frame).
inline std::vector<std::unique_ptr<preproc::SpaceMap>> spaceMapsOf(const preproc::HexMesh& mesh,
                                                                   double extension = 3.0) {
    const preproc::NodeHexAdjacency adjacency(static_cast<Index>(mesh.nodes.size()), mesh.hexes);
    std::vector<preproc::BlockLattice> blocks;
    for (const preproc::HexVolume& v : mesh.volumes) {
        blocks.push_back(preproc::indexBlock(mesh, v, adjacency));
    }
    const preproc::GluingResult glued =
        preproc::glueBlocks(blocks, std::vector<Index>(blocks.size(), 0));
    std::vector<std::unique_ptr<preproc::SpaceMap>> maps;
    for (const preproc::GluedSpace& s : glued.spaces) {
        maps.push_back(std::make_unique<preproc::SpaceMap>(mesh, blocks, s, extension));
    }
    return maps;
}

/// Every home particle sits at X(θ) of its own space, and every overset entry's θ maps back to
/// its particle's X through the other space's map (both to `tolerance` × `scale`); ω equals
/// V / det(∂X/∂θ) there.
inline void expectEntriesReproduceX(const ParticleFile& f,
                                    const std::vector<std::unique_ptr<preproc::SpaceMap>>& maps,
                                    double scale, double tolerance = 1e-12) {
    ASSERT_EQ(maps.size(), f.spaces.size());
    for (Index a = 0; a < f.size(); ++a) {
        const double dtheta = f.spaces[f.space[a]].dtheta;
        const Vec3 X = maps[f.space[a]]->position(f.theta[a] / dtheta);
        ASSERT_LE((X - f.X[a]).norm(), tolerance * scale) << "home particle " << a;
    }
    const OversetEntries& o = f.overset;
    for (std::size_t e = 0; e < o.size(); ++e) {
        const preproc::SpaceMap& map = *maps[o.space[e]];
        const double dtheta = f.spaces[o.space[e]].dtheta;
        const Vec3 u = o.theta[e] / dtheta;
        const Index b = o.particle[e];
        ASSERT_LE((map.position(u) - f.X[b]).norm(), tolerance * scale)
            << "entry " << e << ": particle " << b << " in space " << o.space[e];
        const double det = map.jacobian(u).determinant() / (dtheta * dtheta * dtheta);
        ASSERT_NEAR(o.omega[e], f.volume[b] / det, 1e-12 * o.omega[e]) << "entry " << e;
    }
}

/// (particle, space) → index of its overset entry.
inline std::map<std::pair<Index, Index>, std::size_t> entryOf(const ParticleFile& f) {
    std::map<std::pair<Index, Index>, std::size_t> out;
    for (std::size_t e = 0; e < f.overset.size(); ++e) {
        out[{f.overset.particle[e], f.overset.space[e]}] = e;
    }
    return out;
}

}  // namespace gsph::test
