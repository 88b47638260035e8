// SPDX-License-Identifier: MIT
// The case file of gsph-solve (TOML; docs/case-format.md). Parsed into plain structs; every
// fault is an InputError "FILE:LINE: what" naming the key, so the user can fix it at once.
// Unknown keys are errors (a misspelt key must never be silently ignored).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "forces/artificial_viscosity.hpp"
#include "material_config.hpp"  // MaterialSpec: [[material]] tables and material files

namespace gsph::solver {

struct BodySpec {
    std::string group;  ///< physical-group name in the particle file, or the body id as text
    std::string material;
    Vec3 velocity = Vec3::Zero();  ///< initial velocity [m/s]
    int line = 0;
};

struct SetSpec {
    std::string name;              ///< named particle set of the particle file
    bool fixed = false;            ///< v = 0
    Vec3 velocity = Vec3::Zero();  ///< prescribed velocity [m/s] when not fixed
    int line = 0;
};

struct CaseConfig {
    std::filesystem::path caseFile;
    std::filesystem::path particles;  ///< resolved against the case file's folder
    int particlesLine = 0;            ///< where [run] particles is set (for messages)
    double endTime = 0.0;             ///< [s]
    double outputInterval = 0.0;      ///< [s]
    double cfl = 0.3;
    double kappa = 1.2;
    ViscosityCoefficients viscosity{1.0, 1.0};
    double hourglass = 0.1;
    /// [s] of simulated time between checkpoints (default: output_interval; 0 = only on a
    /// signal).
    double checkpointInterval = 0.0;
    /// A stable Δt below this fraction of the first Δt stops the run (0 = off).
    double minDtRatio = 1e-3;
    std::vector<MaterialSpec> materials;
    std::vector<BodySpec> bodies;
    std::vector<SetSpec> sets;
};

/// Parses and validates a case file. Throws InputError "FILE:LINE: ..." on any fault.
CaseConfig readCaseFile(const std::filesystem::path& path);

}  // namespace gsph::solver
