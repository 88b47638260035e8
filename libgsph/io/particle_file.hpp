// SPDX-License-Identifier: MIT
// The particle file (DESIGN §1, §2): what gsph-preproc writes and gsph-solve reads. HDF5,
// format "gsph-particles" 1.4, layout in docs/formats.md (1.1 added /overset and
// /particles/transient, 1.2 /set_areas, 1.3 /spaces/nodes, 1.4 /dimension; older files still
// read, without what they lack: they are 3-D).
//
// Invariants (checked by validateParticleFile, on write and on read):
//   * every per-particle array has N entries (latticeIndex: N or none);
//   * particles are sorted by body, then by space: bodies and spaces are contiguous ranges, and
//     each space belongs to one body;
//   * space ids index `spaces`, body ids index `bodies`, set entries are sorted particle indices;
//   * volumes are positive; lattice indices lie inside their space's cells;
//   * overset entries (DESIGN §6) are sorted by (space, particle), unique, name an existing
//     particle and another space of its body, carry finite θ within 2·kappa·Δθ of that space's
//     lattice and a positive finite ω; `transient` (N entries, or none when there are no
//     entries) is 1 exactly for the particles that have an entry;
//   * nodes (the lattice corners' reference positions, optional) hold nodeCount(spaces) finite
//     rows: space after space, each in lattice order (i fastest), nodeExtent nodes per index;
//   * dimension is 2 or 3; a 2-D file (a layout in the x-y plane, volumes per metre of depth)
//     has one cell along every space's third index, X_z = 0 and θ_z = 0 for every particle
//     and overset entry (its nodes are the cells' corners at z = 0 and z = 1: a slab of unit
//     depth).
// Ownership: plain values; writeParticleFile writes atomically (io/atomic_file.hpp).
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/provenance.hpp"
#include "particles/reference.hpp"

namespace gsph {

inline constexpr const char* kParticleFormat = "gsph-particles";
inline constexpr int kParticleFormatMajor = 1;  ///< readers reject another major version
inline constexpr int kParticleFormatMinor = 4;  ///< additions that old readers may ignore

/// One body: a gmsh physical volume group (or the whole mesh when there is none).
struct BodyInfo {
    std::string name;      ///< the group's name; empty if it has none
    Index sourceTag = -1;  ///< the group's tag in the source mesh; -1 if none
};

/// Lattice nodes of a space along each index: n + 1, or n along a periodic index (node n is
/// node 0 there, so a seam's nodes are shared).
std::array<std::size_t, 3> nodeExtent(const LatticeSpace& space);
/// Σ over the spaces of their nodes (the rows of /spaces/nodes).
std::size_t nodeCount(const std::vector<LatticeSpace>& spaces);
/// Row of lattice node (i, j, k) of a space within that space's nodes (indices wrapped along
/// periodic axes).
std::size_t nodeRow(const LatticeSpace& space, int i, int j, int k);

struct ParticleFile {
    // Per particle (N entries), sorted by body then space; lattice order within a space.
    std::vector<Vec3> X;                             ///< reference position [m]
    std::vector<Vec3> theta;                         ///< coordinates in the home space [θ units]
    std::vector<double> volume;                      ///< exact cell volume [m³]
    std::vector<Index> space;                        ///< home space id
    std::vector<Index> body;                         ///< body id
    std::vector<std::array<Index, 3>> latticeIndex;  ///< (i,j,k) in the home space; optional
    /// 1 if the particle is transient (has an overset entry), else 0; N entries, or none for a
    /// file without overset data (format 1.0).
    std::vector<std::int8_t> transient;
    OversetEntries overset;  ///< θ of transient particles in other spaces (DESIGN §6)

    std::vector<LatticeSpace> spaces;                ///< per space: cells, periodic flags, Δθ
    std::vector<BodyInfo> bodies;                    ///< per body id
    std::map<std::string, std::vector<Index>> sets;  ///< named particle sets (sorted indices)
    /// Per set (optional; since 1.2): the outward area vector of each member's cell faces on the
    /// set's surface in the reference configuration, in the order of the set's indices [m²]
    /// (what a pressure on the set acts on, boundary/pressure.hpp).
    std::map<std::string, std::vector<Vec3>> setAreas;
    /// Reference positions of the lattice nodes (the corners of the particles' cells: a mesh's
    /// hex nodes, or a --lattice box's corners) [m]; optional (since 1.3): empty or
    /// nodeCount(spaces) rows, space after space, each in lattice order (i fastest).
    std::vector<Vec3> nodes;
    /// 3, or 2 for a layout in the x-y plane (plane strain or axisymmetric, as the run says;
    /// volumes and set areas per metre of depth; since 1.4, older files are 3-D).
    int dimension = 3;
    Provenance provenance;

    Index size() const { return static_cast<Index>(X.size()); }
};

/// The lattice cell (i, j, k) of each particle in its space: /particles/lattice_index, or (without
/// it) the particle's rank in its space in lattice order (i fastest).
std::vector<std::array<Index, 3>> latticeCells(const ParticleFile& file);

/// For an axisymmetric run of a 2-D file (x the radius, y the axis): the area vectors of set
/// `set` swept about the y axis, in the set's order [m²]. A member's stored area (per metre of
/// depth) is split into the edges of its cell whose outward areas |e| n_e add up to it (the
/// faces gsph-preproc summed), and each edge sweeps 2π r_e |e| n_e, r_e its midpoint's radius:
/// exact for straight edges. Where the areas do not split so (a --lattice file's shared faces,
/// or a file without nodes) the member's own radius stands in: 2π X_r A, exact to O(Δr/r).
/// Throws InputError if the file is not 2-D or has no such set areas.
std::vector<Vec3> sweptSetAreas(const ParticleFile& file, const std::string& set);

/// Throws InputError naming the first violated invariant (see the header comment).
void validateParticleFile(const ParticleFile& file);

/// Writes `file` to `path` atomically (temporary name + rename). Throws InputError if the
/// content is invalid, IoError if writing fails; nothing is left behind on failure.
void writeParticleFile(const std::filesystem::path& path, const ParticleFile& file);

/// Reads and validates a particle file. Throws IoError naming the file if it is missing, not a
/// gsph-particles file, of an unsupported major version, or inconsistent.
ParticleFile readParticleFile(const std::filesystem::path& path);

/// readParticleFile in a child process (io/child_process.hpp): a damaged or crafted file that
/// crashes HDF5's own parser (tests/fuzz/third_party_findings) is an IoError naming the file
/// and the signal instead of a crash of the caller. Same results and errors otherwise. A reader
/// that takes longer than `deadlineSeconds` (0: 60 s plus 1 s per 20 MB of file) is stopped: an
/// IoError too (HDF5 loops on some damaged files).
ParticleFile readParticleFileIsolated(const std::filesystem::path& path,
                                      unsigned deadlineSeconds = 0);

}  // namespace gsph
