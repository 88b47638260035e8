// SPDX-License-Identifier: MIT
// `gsph-solve --material-point MATERIAL.toml --path PATH [-o OUT.csv]`: drives one material
// point along a path (materials/material_point_driver.hpp) and writes a CSV of time, strain,
// stress components, pressure, von Mises stress, plastic strain, temperature, damage and
// plastic work (docs/materials.md). PATH is either a compact form (.toml: uniaxial strain,
// uniaxial stress or simple shear at a strain rate and temperature) or a table of F (.csv).
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "materials/material_point_driver.hpp"

namespace gsph::solver {

struct MaterialPointOptions {
    std::string material;               ///< material file (materials/*.toml)
    std::string path;                   ///< path file (.toml compact form or .csv F table)
    std::optional<double> temperature;  ///< initial temperature, overrides the path's [K]
    int substeps = 100;                 ///< increments per row interval of a .csv path
    bool requested() const { return !material.empty(); }
};

/// Adds --material-point, --path, --temperature, --substeps to gsph-solve's command line; the
/// positional case file becomes optional (one of the two must be given).
void addMaterialPointOptions(CLI::App& app, MaterialPointOptions& options);

/// Reads a path file: .toml (compact form) or .csv (time and F, row by row). InputError
/// "FILE:LINE: what" on a bad file.
LoadingPath readLoadingPath(const std::filesystem::path& file, int substeps);

/// The driver's output as CSV (header + one row per record).
void writeMaterialPointCsv(std::ostream& out, const std::vector<MaterialPointRecord>& rows);

/// Runs the driver: CSV to `output` (atomically) or to stdout when empty. Returns the exit code;
/// errors go to stderr as one line.
int runMaterialPoint(const MaterialPointOptions& options, const std::string& output);

}  // namespace gsph::solver
