// SPDX-License-Identifier: MIT
// ParaView output of gsph-post (docs/formats.md, "gsph-post output"): one .vtu point cloud per
// snapshot, one .vtp crack surface per snapshot, and .pvd time series of either.
// Point fields of the .vtu: displacement, velocity (3 components), stress (Cauchy, 9
// components, row-major), von_mises, pressure, plastic_strain, temperature, damage, J,
// reference_volume (float64), body, space (int32), transient (uint8). Cell fields of the .vtp:
// reference_area (float64), bond (int32, 2 components). Files are written under a temporary
// name and renamed.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "crack_surface.hpp"
#include "io/snapshot.hpp"

namespace gsph::post {

/// von Mises stress √(3/2 s:s) of a Cauchy stress [Pa].
double vonMises(const Mat3& sigma);

/// Scalar fields of a particle by name (vectors as their magnitude): displacement, velocity,
/// von_mises, pressure, plastic_strain, temperature, damage, J, body, space, transient.
const std::vector<std::string>& scalarFieldNames();
bool isScalarField(const std::string& name);
/// Throws InputError for a name not in scalarFieldNames().
double scalarField(const Snapshot& snapshot, std::size_t particle, const std::string& name);

void writeVtu(const std::filesystem::path& path, const Snapshot& snapshot);

/// A crack surface as VTK polygons (may be empty: no points, no polygons).
void writeVtp(const std::filesystem::path& path, const CrackSurface& surface);

/// A ParaView collection of (time, file name relative to the .pvd) entries.
void writePvd(const std::filesystem::path& path,
              const std::vector<std::pair<double, std::string>>& entries);

}  // namespace gsph::post
