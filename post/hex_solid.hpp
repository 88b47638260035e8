// SPDX-License-Identifier: MIT
// The solid, not a cloud: the hexahedral cells of each generalized space in the current
// configuration (docs/formats.md, "gsph-post output"). Every particle is the centre of one
// lattice cell (i, j, k) of its space; the cell's eight corners are lattice nodes, shared by
// the cells around them (across a periodic seam too: node n of a periodic index is node 0).
//
//   * Reference node positions X_n: the particle file's /spaces/nodes (since 1.3: the mesh's
//     hex nodes, or a --lattice box's corners). An older file has none: X_n is then estimated
//     from the particles, X_n = mean over the cells a around n of X_a + M_a (u_n − u_a), with
//     M_a = ∂X/∂u by central (one-sided at a boundary) differences of the neighbouring
//     particles' X along the lattice (exact for an affine map X(u)).
//   * Current node positions: x_n = mean over the cells a around n of x_a + F_a (X_n − X_a),
//     continuous across a space. For an affine motion (uniform F, x = F X + c) every x_n is
//     F X_n + c, so the hexahedra's volume is Σ V J to round-off; for a general motion it is
//     not (gsph-post reports the difference).
//   * Each space is its own piece: spaces of one body abut or overlap (overset), and their
//     nodes are not shared.
// Ownership: plain values, built once per run and reused for every snapshot.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/particle_file.hpp"
#include "io/snapshot.hpp"

namespace gsph::post {

/// One space's hexahedra.
struct SolidPiece {
    Index space = 0, body = 0;
    std::vector<Vec3> nodeX;  ///< reference positions of the piece's nodes [m]
    /// Node ids of each hexahedron in VTK_HEXAHEDRON order: the lattice corners (0,0,0),
    /// (1,0,0), (1,1,0), (0,1,0), then the same at k + 1 (mirrored in k where the space's frame
    /// is left-handed, so that every cell has a positive volume).
    std::vector<std::array<Index, 8>> hexes;
    std::vector<Index> particle;     ///< the particle (snapshot index) of each hexahedron
    std::vector<Index> cellsAround;  ///< per node: how many hexahedra share it
};

class HexSolid {
  public:
    /// From the run's particle file; `X` are the snapshot's reference positions. Throws
    /// InputError naming `source` if the file does not belong to the run (another particle
    /// count or positions).
    HexSolid(const ParticleFile& file, const std::vector<Vec3>& X, const std::string& source);

    const std::vector<SolidPiece>& pieces() const { return pieces_; }
    /// True if the reference nodes were estimated (a file without /spaces/nodes).
    bool estimatedNodes() const { return estimated_; }
    std::size_t hexahedra() const;
    /// Exact reference volume of the hexahedra [m³] (Σ over cells of the trilinear volume).
    double referenceVolume() const;
    /// Σ V_a over the particles with a cell, V from the particle file [m³].
    double particleVolume() const { return particleVolume_; }
    /// Σ V_a det F_a of a snapshot, V from the particle file [m³].
    double particleVolume(const Snapshot& snapshot) const;

    /// Σ of the hexahedra's exact volumes at a snapshot's current nodes [m³].
    double currentVolume(const Snapshot& snapshot) const;

    /// Current positions of a piece's nodes in a snapshot (see the header comment).
    std::vector<Vec3> currentNodes(const SolidPiece& piece, const Snapshot& snapshot) const;

  private:
    std::vector<SolidPiece> pieces_;
    std::vector<double> volume_;  // V per particle, from the particle file
    double particleVolume_ = 0.0;
    bool estimated_ = false;
};

/// Exact volume (spaces/hexahedron.hpp) of a trilinear hexahedron with corners in
/// VTK_HEXAHEDRON order [m³]; negative if it is inverted.
double hexahedronVolume(const std::array<Vec3, 8>& corners);

/// Σ of the hexahedra's exact volumes with their nodes at `nodes` [m³].
double hexahedraVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes);

/// Where a run's particle file is, or why none was found.
struct ParticleFileLocation {
    std::optional<std::filesystem::path> path;
    std::string why;  ///< how it was found, or why not (one line)
};

/// The particle file of a run: `given` if not empty; else the one the run's checkpoint.h5 names
/// (its /run/inputs entry "particles", as named, else its file name in RUNDIR); else
/// RUNDIR/particles.h5. The checkpoint is read in a child process (a damaged file cannot crash
/// the caller). Never throws for a missing file: `path` is then empty.
ParticleFileLocation locateParticleFile(const std::filesystem::path& runDir,
                                        const std::filesystem::path& given);

}  // namespace gsph::post
