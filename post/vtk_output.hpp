// SPDX-License-Identifier: MIT
// ParaView output of gsph-post (docs/formats.md, "gsph-post output"): per snapshot one .vtu
// point cloud, the solid (a .vtm of one .vtu of hexahedra per space, quadrilaterals for a 2-D
// run, hex_solid.hpp; optionally a 2-D run's section revolved) and one .vtp crack surface, and
// .pvd time series of each.
// Per-particle arrays (point data of the cloud, cell data of the solid): displacement, velocity
// (3 components), stress (Cauchy, 9 components XX … ZZ, row-major), von_mises, pressure,
// plastic_strain, temperature, damage, bond_damage, J, radius, reference_volume (float64), id,
// body, space (int32), transient (uint8). Field data of every .vtu: TimeValue, units
// ("NAME=UNIT"), body_names and set_names (when the particle file is at hand). Cell fields of
// the .vtp: reference_area (float64), bond (int32, 2 components). Files are written under a
// temporary name and renamed.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkSmartPointer.h>

#include "crack_surface.hpp"
#include "hex_solid.hpp"
#include "io/snapshot.hpp"
#include "materials/stress_measures.hpp"

class vtkUnstructuredGrid;

namespace gsph::post {

using gsph::vonMises;  // materials/stress_measures.hpp

/// Scalar fields of a particle by name (vectors as their magnitude): displacement, velocity,
/// von_mises, pressure, plastic_strain, temperature, damage, J, body, space, transient.
const std::vector<std::string>& scalarFieldNames();
bool isScalarField(const std::string& name);
/// Throws InputError for a name not in scalarFieldNames().
double scalarField(const Snapshot& snapshot, std::size_t particle, const std::string& name);

/// The scale of ParaView's Point Gaussian for particle i, so that neighbours' splats touch: half
/// the edge of a cube of its current volume V J (3-D), or of a square of its current area (2-D:
/// V J per metre of depth in plane strain, V J / 2πr of a ring in an axisymmetric run).
double splatRadius(const Snapshot& snapshot, std::size_t i);

/// Names for the field data: the particle file's bodies (by body id) and sets (empty: not known).
struct RunLabels {
    std::vector<std::string> bodyNames, setNames;
};

/// The particles as a point cloud (a VTK_VERTEX per particle).
void writeVtu(const std::filesystem::path& path, const Snapshot& snapshot,
              const RunLabels& labels = {});

/// The cells of a piece as a VTK cell array: VTK_HEXAHEDRON node ids, or VTK_QUAD ones for a
/// 2-D piece (solidCellType).
vtkSmartPointer<vtkCellArray> solidCells(const SolidPiece& piece);
int solidCellType(const SolidPiece& piece);

/// One piece of the solid in a snapshot: its cells at the current node positions, the
/// particle arrays as cell data, node_displacement (x_n − X_n) as point data.
vtkSmartPointer<vtkUnstructuredGrid> solidGrid(const HexSolid& solid, const SolidPiece& piece,
                                               const Snapshot& snapshot, const RunLabels& labels);

/// One 2-D piece swept about the y axis into `sectors` sectors (revolveSection): hexahedra and
/// wedges with the arrays of their particles as cell data, vectors (3 components) and tensors
/// (9) rotated into the sector: the run's frame (x, y, z) is the local (r, axis, hoop) frame,
/// turned by the sector's middle angle φ about y (v = (v_r, v_y, v_θ) becomes
/// (v_r cos φ − v_θ sin φ, v_y, v_r sin φ + v_θ cos φ), σ becomes R σ Rᵀ).
vtkSmartPointer<vtkUnstructuredGrid> revolvedGrid(const HexSolid& solid, const SolidPiece& piece,
                                                  const Snapshot& snapshot, const RunLabels& labels,
                                                  int sectors);

/// The block name of a piece: "BODY space S" (BODY = the body's name, or "body B").
std::string solidBlockName(const SolidPiece& piece, const RunLabels& labels);

/// Writes the solid of a snapshot: each piece as STEM_sS.vtu (S its space) beside `vtm`, then
/// the multiblock file `vtm` (STEM.vtm) naming them, one block per space. `sectors` > 0: each
/// piece revolved (revolvedGrid) instead.
void writeSolid(const std::filesystem::path& vtm, const HexSolid& solid, const Snapshot& snapshot,
                const RunLabels& labels, int sectors = 0);

/// A crack surface as VTK polygons (may be empty: no points, no polygons).
void writeVtp(const std::filesystem::path& path, const CrackSurface& surface);

/// A ParaView collection of (time, file name relative to the .pvd) entries.
void writePvd(const std::filesystem::path& path,
              const std::vector<std::pair<double, std::string>>& entries);

}  // namespace gsph::post
