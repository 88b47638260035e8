// SPDX-License-Identifier: MIT
// ParaView output of gsph-post: one .vtu point cloud per snapshot and a .pvd time series.
// Point fields: displacement, velocity, stress (Cauchy, 9 components), von_mises, pressure,
// J, body, space. Files are written under a temporary name and renamed.
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

#include "io/snapshot.hpp"

namespace gsph::post {

/// von Mises stress √(3/2 s:s) of a Cauchy stress [Pa].
double vonMises(const Mat3& sigma);

void writeVtu(const std::filesystem::path& path, const Snapshot& snapshot);

/// A ParaView collection of (time, file name relative to the .pvd) entries.
void writePvd(const std::filesystem::path& path,
              const std::vector<std::pair<double, std::string>>& entries);

}  // namespace gsph::post
