// SPDX-License-Identifier: MIT
// Pictures without a display (VTK offscreen rendering; Debian's VTK needs an X server, which
// gsph-post provides through xvfb-run when DISPLAY is unset):
//   * the deformed particles of a snapshot coloured by a field, with a colour bar and the time;
//   * a plot of history.csv: the energy channels against time.
// PNGs are written under a temporary name and renamed.
#pragma once

#include <filesystem>
#include <string>

#include "io/snapshot.hpp"

namespace gsph::post {

/// Fields a picture can show: von_mises, pressure, displacement, velocity (magnitudes), J.
bool isPictureField(const std::string& field);

void renderSnapshot(const Snapshot& snapshot, const std::string& field,
                    const std::filesystem::path& png, int width = 1200, int height = 800);

/// Plots every energy column of a history.csv against time. Throws InputError naming the file
/// if it has no such columns.
void plotHistory(const std::filesystem::path& historyCsv, const std::filesystem::path& png,
                 int width = 1000, int height = 600);

}  // namespace gsph::post
