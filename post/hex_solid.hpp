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
//   * A 2-D particle file (a layout in the x-y plane) gives quadrilaterals instead: one per
//     particle, its corners the z = 0 layer of the cell's nodes, moved as above (the z column
//     of F plays no part, so an axisymmetric run's hoop stretch F_zz = r/R does not tilt
//     them). Volumes are then areas [m²] (per metre of depth, as the file's V). An
//     axisymmetric section can be swept about the y axis into a 3-D body (revolveSection).
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

/// One space's cells: hexahedra (a 3-D file) or quadrilaterals (a 2-D file).
struct SolidPiece {
    Index space = 0, body = 0;
    std::vector<Vec3> nodeX;  ///< reference positions of the piece's nodes [m]
    /// Node ids of each hexahedron in VTK_HEXAHEDRON order: the lattice corners (0,0,0),
    /// (1,0,0), (1,1,0), (0,1,0), then the same at k + 1 (mirrored in k where the space's frame
    /// is left-handed, so that every cell has a positive volume). Empty in 2-D.
    std::vector<std::array<Index, 8>> hexes;
    /// 2-D: node ids of each quadrilateral in VTK_QUAD order, counter-clockwise seen from +z:
    /// the lattice corners (0,0), (1,0), (1,1), (0,1) (reversed where the space's frame is
    /// left-handed). Empty in 3-D.
    std::vector<std::array<Index, 4>> quads;
    std::vector<Index> particle;     ///< the particle (snapshot index) of each cell
    std::vector<Index> cellsAround;  ///< per node: how many cells share it

    std::size_t cells() const { return hexes.size() + quads.size(); }
    bool planar() const { return !quads.empty(); }
};

class HexSolid {
  public:
    /// From the run's particle file; `X` are the snapshot's reference positions. Throws
    /// InputError naming `source` if the file does not belong to the run (another particle
    /// count or positions).
    HexSolid(const ParticleFile& file, const std::vector<Vec3>& X, const std::string& source);

    const std::vector<SolidPiece>& pieces() const { return pieces_; }
    /// The particle file's dimension: 3 (hexahedra) or 2 (quadrilaterals in the x-y plane).
    int dimension() const { return dimension_; }
    /// True if the reference nodes were estimated (a file without /spaces/nodes).
    bool estimatedNodes() const { return estimated_; }
    /// Σ over the pieces of their cells (hexahedra in 3-D, quadrilaterals in 2-D).
    std::size_t cells() const;
    std::size_t hexahedra() const;
    std::size_t quadrilaterals() const;
    /// Exact reference volume of the hexahedra [m³] (Σ over cells of the trilinear volume);
    /// in 2-D the quadrilaterals' area [m²].
    double referenceVolume() const;
    /// Σ V_a over the particles with a cell, V from the particle file [m³; 2-D: m² per m].
    double particleVolume() const { return particleVolume_; }
    /// Σ V_a det F_a of a snapshot, V from the particle file [m³]; in 2-D det of F's in-plane
    /// 2×2 block, so that it compares with the quadrilaterals' area (an axisymmetric run's
    /// F_zz = r/R is no change of the section's area).
    double particleVolume(const Snapshot& snapshot) const;

    /// Σ of the cells' exact volumes (2-D: areas) at a snapshot's current nodes.
    double currentVolume(const Snapshot& snapshot) const;

    /// Current positions of a piece's nodes in a snapshot (see the header comment).
    std::vector<Vec3> currentNodes(const SolidPiece& piece, const Snapshot& snapshot) const;

  private:
    std::vector<SolidPiece> pieces_;
    std::vector<double> volume_;  // V per particle, from the particle file
    double particleVolume_ = 0.0;
    int dimension_ = 3;
    bool estimated_ = false;
};

/// Exact volume (spaces/hexahedron.hpp) of a trilinear hexahedron with corners in
/// VTK_HEXAHEDRON order [m³]; negative if it is inverted.
double hexahedronVolume(const std::array<Vec3, 8>& corners);

/// Σ of the hexahedra's exact volumes with their nodes at `nodes` [m³].
double hexahedraVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes);

/// Signed area of a quadrilateral's projection on the x-y plane (the shoelace formula: exact for
/// a bilinear cell), positive if its corners run counter-clockwise seen from +z [m²].
double quadrilateralArea(const std::array<Vec3, 4>& corners);

/// Σ of the quadrilaterals' signed areas with their nodes at `nodes` [m²].
double quadrilateralsArea(const SolidPiece& piece, const std::vector<Vec3>& nodes);

/// Σ of a piece's cells' volumes (hexahedra) or areas (quadrilaterals) at `nodes`.
double cellsVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes);

/// A 2-D piece's quadrilaterals swept about the y axis (x = r the radius, y the axis) into
/// `sectors` equal sectors: a point (r, y) at angle φ is (r cos φ, y, r sin φ), and sector s
/// spans φ from 2π s/N to 2π (s + 1)/N with straight edges (a prism over an N-gon for a
/// rectangle on the axis: volume π R² L · N/(2π) sin(2π/N)). Each quadrilateral gives one cell
/// per sector: a VTK_HEXAHEDRON, or a VTK_WEDGE where an edge of it lies on the axis (its two
/// nodes there are one node of every sector); a cell with a single corner on the axis stays a
/// hexahedron with two coincident nodes. Nodes on the axis are those at x = 0 in the reference
/// configuration; they are kept on it (x = 0) in the current one, where the node estimate may
/// put them a little off.
struct RevolvedCells {
    static constexpr int kHexahedron = 12, kWedge = 13;  ///< VTK_HEXAHEDRON, VTK_WEDGE
    std::vector<Vec3> nodes;                             ///< current positions [m]
    std::vector<Vec3> nodeX;                             ///< reference positions [m]
    std::vector<int> type;                               ///< per cell: kHexahedron or kWedge
    /// Per cell: its corners as a hexahedron in VTK_HEXAHEDRON order (the quadrilateral at the
    /// sector's first angle, then at its last), ids repeated where corners lie on the axis.
    std::vector<std::array<Index, 8>> hexes;
    /// Per cell: the VTK node ids (8 for a hexahedron, 6 for a wedge), from offsets[c].
    std::vector<Index> offsets, connectivity;
    std::vector<Index> particle;  ///< per cell: the particle (snapshot index)
    std::vector<double> angle;    ///< per cell: its sector's middle angle φ [rad]
    std::size_t cells() const { return type.size(); }
    /// Σ of the cells' exact volumes at the current nodes [m³].
    double volume() const;
};

/// The revolved cells of a 2-D piece at its current nodes `nodes` (HexSolid::currentNodes).
RevolvedCells revolveSection(const SolidPiece& piece, const std::vector<Vec3>& nodes, int sectors);

/// The volume of a 2-D piece's section at `nodes` revolved a full turn about the y axis [m³]:
/// 2π ∫ r dA over its quadrilaterals (Pappus; nodes on the axis as in revolveSection), what
/// revolveSection's N-gon approaches as N grows.
double solidOfRevolutionVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes);

/// Throws InputError naming `source` unless the solid can be revolved into `sectors` sectors: a
/// 2-D file whose nodes all lie at x ≥ 0 (to round-off), and few enough cells × sectors for
/// RevolvedCells' Index node ids.
void requireRevolvableSection(const HexSolid& solid, int sectors, const std::string& source);

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
