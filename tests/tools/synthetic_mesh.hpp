// SPDX-License-Identifier: MIT
// Hex meshes built in code for the preprocessor's tests: structured blocks from a node map,
// with node ids, hex order and each hex's local node order shuffled, so that nothing can lean
// on the order in which a mesher happens to write things.
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "hex_mesh.hpp"
#include "hex_topology.hpp"
#include "lattice_transform.hpp"

namespace gsph::test {

using preproc::HexMesh;
using preproc::Int3;

/// Builds a HexMesh block by block; nodes with the same key are one node (shared by blocks).
class MeshBuilder {
  public:
    using Key = std::array<int, 3>;

    explicit MeshBuilder(unsigned seed = 1) : rng_(seed) { mesh_.source = "synthetic.msh"; }

    /// Adds an ni×nj×nk block: lattice node (i,j,k) is node key(i,j,k) at position(key).
    /// Each hex gets its 8 nodes in gmsh order under a random rotation of the cube (so its
    /// Jacobian stays positive when the block's (i,j,k) frame is right-handed).
    void addBlock(int volumeTag, Int3 n, const std::function<Key(int, int, int)>& key,
                  const std::function<Vec3(const Key&)>& position,
                  const std::function<bool(int, int, int)>& skipCell = nullptr) {
        preproc::HexVolume volume{volumeTag, static_cast<Index>(mesh_.hexes.size()), 0};
        std::vector<std::array<Index, 8>> hexes;
        for (int k = 0; k < n[2]; ++k) {
            for (int j = 0; j < n[1]; ++j) {
                for (int i = 0; i < n[0]; ++i) {
                    if (skipCell && skipCell(i, j, k)) continue;
                    std::array<Index, 8> corner{};  // corner bits order
                    for (int c = 0; c < 8; ++c) {
                        corner[c] =
                            node(key(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1)), position);
                    }
                    hexes.push_back(shuffledGmshOrder(corner));
                }
            }
        }
        std::shuffle(hexes.begin(), hexes.end(), rng_);
        for (const auto& h : hexes) {
            mesh_.hexes.push_back(h);
            mesh_.hexTags.push_back(mesh_.hexTags.size() + 1);
        }
        volume.hexCount = static_cast<Index>(hexes.size());
        mesh_.volumes.push_back(volume);
    }

    /// The mesh with node ids renumbered at random.
    HexMesh build() {
        std::vector<Index> perm(mesh_.nodes.size());
        std::iota(perm.begin(), perm.end(), 0);
        std::shuffle(perm.begin(), perm.end(), rng_);
        HexMesh out = mesh_;
        for (std::size_t n = 0; n < perm.size(); ++n) out.nodes[perm[n]] = mesh_.nodes[n];
        for (auto& h : out.hexes) {
            for (Index& n : h) n = perm[n];
        }
        for (auto& g : out.surfaceGroups) {
            for (auto& q : g.quads) {
                for (Index& n : q) n = perm[n];
            }
        }
        return out;
    }

    /// Puts every hex into one volume (to build blocks that are not one structured grid).
    void mergeVolumes(int volumeTag) {
        mesh_.volumes = {preproc::HexVolume{volumeTag, 0, static_cast<Index>(mesh_.hexes.size())}};
    }

    HexMesh& raw() { return mesh_; }
    Index nodeOf(const Key& k) const { return ids_.at(k); }

  private:
    Index node(const Key& k, const std::function<Vec3(const Key&)>& position) {
        const auto [it, added] = ids_.try_emplace(k, static_cast<Index>(mesh_.nodes.size()));
        if (added) mesh_.nodes.push_back(position(k));
        return it->second;
    }

    std::array<Index, 8> shuffledGmshOrder(const std::array<Index, 8>& corner) {
        const auto& rotations = preproc::SignedPermutation::rotations();
        const auto& R = rotations[std::uniform_int_distribution<std::size_t>(0, 23)(rng_)];
        std::array<Index, 8> local{};
        for (int l = 0; l < 8; ++l) {
            // gmsh local node l sits at corner bits kGmshCorner[l] of the hex's own frame; map
            // that corner through R (about the cube centre) into the block frame.
            const int b = preproc::kGmshCorner[l];
            const Int3 centred = {2 * (b & 1) - 1, 2 * (b >> 1 & 1) - 1, 2 * (b >> 2 & 1) - 1};
            const Int3 r = R.apply(centred);
            const int bits = (r[0] > 0) | (r[1] > 0) << 1 | (r[2] > 0) << 2;
            local[l] = corner[bits];
        }
        return local;
    }

    HexMesh mesh_;
    std::map<Key, Index> ids_;
    std::mt19937 rng_;
};

/// Cartesian key/position helpers: node key = global lattice index, position = spacing * key.
inline std::function<MeshBuilder::Key(int, int, int)> offsetKey(Int3 origin) {
    return [origin](int i, int j, int k) {
        return MeshBuilder::Key{origin[0] + i, origin[1] + j, origin[2] + k};
    };
}

}  // namespace gsph::test
