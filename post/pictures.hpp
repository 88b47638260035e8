// SPDX-License-Identifier: MIT
// Pictures without a display (VTK offscreen rendering; Debian's VTK needs an X server, which
// gsph-post provides through xvfb-run when DISPLAY is unset):
//   * the deformed body of a snapshot (its solid, else its particles) coloured by a field, with a
//     colour bar and the time;
//   * plots of history.csv columns against time (energies, momentum), columns found by name.
// PNGs are written under a temporary name and renamed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "hex_solid.hpp"
#include "io/snapshot.hpp"

namespace gsph::post {

/// The deformed body of a snapshot coloured by a scalar field (vtk_output.hpp,
/// scalarFieldNames()), with a colour bar and the time: the solid's hexahedra when `solid` is
/// given (a compact 3-D body cut through its middle to show the inside), else the particles.
void renderSnapshot(const Snapshot& snapshot, const std::string& field,
                    const std::filesystem::path& png, int width = 1200, int height = 800,
                    const HexSolid* solid = nullptr);

/// history.csv as columns by name (the solver adds columns: never rely on their order).
struct HistoryTable {
    std::vector<std::string> names;
    std::vector<std::vector<double>> columns;
    /// The column called `name`, or nullptr.
    const std::vector<double>* column(const std::string& name) const;
};

/// Reads a history.csv. Throws InputError naming the file and line on a malformed row.
HistoryTable readHistory(const std::filesystem::path& historyCsv);

/// Plots the columns of `wanted` that the history has against its "time" column. Returns
/// false (and writes nothing) if it has no time column or none of them.
bool plotHistory(const HistoryTable& history, const std::vector<std::string>& wanted,
                 const std::string& yTitle, const std::filesystem::path& png, int width = 1000,
                 int height = 600);

}  // namespace gsph::post
