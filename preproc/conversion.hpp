// SPDX-License-Identifier: MIT
// Hex mesh → particles (DESIGN §2), after the mesh has left gmsh: bodies from physical volume
// groups, blocks indexed (block_indexing), blocks glued into spaces (space_gluing), one particle
// per hex at its parametric centre with its exact volume and θ = (i+½, j+½, k+½)·Δθ, Δθ = 1,
// and particle sets from physical surface groups. In a body of several spaces (DESIGN §6),
// particles inside a space that outranks their own are cut and transient particles get θ in
// the other spaces (overset.hpp).
//
// Bodies: body id = rank of the physical volume group's tag. With no physical volume group at
// all, the whole mesh is body 0. With groups, a volume with hexahedra in no group, or in two,
// is an error (gmsh -3 would silently drop it from a .msh; here it is reported instead).
// Sets: a surface group "name" (or "surface_<tag>" if unnamed) holds every particle whose hex
// has a face on one of its surfaces.
// 2-D meshes (HexMesh::dimension = 2, quads extruded to unit depth) are converted on that slab
// and returned as a 2-D file: every space turned so that its one-cell index is the third,
// X_z = θ_z = 0, set areas in the plane, volumes the cells' areas (per metre of depth).
// Order: particles sorted by body, then space (spaces sorted by body, then smallest volume tag),
// then lattice order within the space (i fastest, then j, then k; cut cells left out).
// Errors: MeshError naming mesh.source and the fault (no hexahedra, inverted element, a block
// collapsed onto an axis, block not structured, bad group, overlap of equal priority, a
// transient that cannot be located); InputError for a bad priority rule or κ.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hex_mesh.hpp"
#include "io/particle_file.hpp"
#include "overset.hpp"

namespace gsph::preproc {

/// Above this condition number of ∂X/∂θ at a particle, gsph-preproc warns (a space near a
/// coordinate axis, or cells far from cubes); the samples stay below 5.
inline constexpr double kIllConditioned = 1e3;
/// Below this ratio of det ∂X/∂θ at a cell's corner to det at its centre, the cell nearly
/// collapses onto a line (a space around a coordinate axis: the metric at the particle may
/// still look fine); gsph-preproc warns. Boxes and parallelepipeds have 1; the O-grid samples
/// stay above 0.6.
inline constexpr double kCollapsingCell = 1e-2;

/// Largest --overset-kappa: transients reach 2κ cells past a space's boundary, and
/// extrapolating the map much farther is not trustworthy.
inline constexpr double kMaxOversetKappa = 3.0;

struct ConversionStats;

struct ConversionOptions {
    std::vector<PriorityRule> priorities;  ///< --priority VOLUME=N (overset.hpp)
    double oversetKappa = 1.5;             ///< --overset-kappa: transients within 2κΔθ
    TransientRule transients = TransientRule::Automatic;  ///< --transients
    /// --lattice H > 0: instead of one particle per hex, the uniform Cartesian layout of
    /// spacing ≈ H filling each body (uniform_lattice.hpp); 0: the hex layout.
    double latticeSpacing = 0.0;
    /// Called once the blocks are glued and their particles placed, before hole cutting and
    /// transients (whose errors name the spaces), so that a tool can report the spaces first.
    std::function<void(const ParticleFile&, const ConversionStats&)> onSpaces;
};

/// Worst condition number σmax/σmin of ∂X/∂θ over a space's particles (hex Jacobian at the
/// particle's centre).
struct MetricReport {
    double condition = 1.0;
    Index worstParticle = 0;
    int oneLayerAxis = -1;          ///< the index along which the space is one cell thick, or −1
    double inPlaneCondition = 1.0;  ///< of the two other columns, if oneLayerAxis ≥ 0
    double cornerRatio = 1.0;  ///< smallest det ∂X/∂θ at a cell corner / det at the centre
    Index worstCornerParticle = 0;
};

struct ConversionStats {
    std::size_t hexes = 0;
    double minEdge = 0.0, maxEdge = 0.0;  ///< shortest and longest hex edge [m]
    int sharedFaces = 0;                  ///< block faces shared by two blocks of one body
    int honouredFaces = 0;                ///< of which inside one space
    bool exhaustiveGluing = true;
    std::vector<std::vector<int>> spaceVolumes;  ///< gmsh volume tags of each space's blocks
    std::vector<MetricReport> metric;            ///< per space
    double oversetKappa = 0.0;                   ///< κ of the transient selection
    std::vector<HoleCutReport> cuts;             ///< per pair (space, a space outranking it)
    std::vector<TransientReport> transients;     ///< per ordered pair of spaces of a body
    /// --lattice only, per body: the spacing along x, y, z [m], the cells of its bounding box,
    /// and the volume of its hexes (the particles' volume is the staircase's).
    struct Lattice {
        Vec3 spacing = Vec3::Zero();
        Int3 cells = {0, 0, 0};
        double meshVolume = 0.0;
    };
    std::vector<Lattice> lattice;
};

struct Conversion {
    ParticleFile particles;  ///< everything but the provenance
    /// source hex (gmsh element tag) per particle; empty for a --lattice layout
    std::vector<std::size_t> elementOfParticle;
    ConversionStats stats;
    std::vector<std::string> warnings;
};

Conversion convertHexMesh(const HexMesh& mesh, const ConversionOptions& options = {});

/// The particle set of a physical surface group: its name, or "surface_<tag>" when unnamed
/// ("curve_<tag>" in 2-D, where the group is a physical curve).
/// Throws MeshError naming mesh.source if the name holds '/' or `particles` has it already.
std::string particleSetName(const HexMesh& mesh, const SurfaceGroup& group,
                            const ParticleFile& particles);

/// Stores set `name` from its (particle, outward face area) pieces, in any order and with
/// repeats: the set's sorted, unique indices and each one's summed area (ParticleFile::setAreas).
/// An empty set is stored empty, with a warning.
void storeParticleSet(const std::string& name, std::vector<std::pair<Index, Vec3>> pieces,
                      Conversion& out);

}  // namespace gsph::preproc
