// SPDX-License-Identifier: MIT
// Materials of gsph-solve (docs/case-format.md, docs/materials.md): a [[material]] table of a
// case file, written inline or naming a material file (`file = "materials/ofhc_copper.toml"`),
// and the material files themselves (the library in materials/). Parsed into a MaterialSpec
// holding the built, validated model; every fault is an InputError "FILE:LINE: what".
//
// Where `file` resolves (first that exists): relative to the case file's folder; then in the
// material library folder — $GSPH_MATERIALS_DIR if set, else PREFIX/share/gsph/materials of an
// installed gsph-solve, else the repository's materials/ — where a leading "materials/" may be left
// out or kept (`ofhc_copper.toml` and `materials/ofhc_copper.toml` name the same library file). An
// absolute path is taken as is.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "materials/material.hpp"

namespace gsph::solver {

struct MaterialSpec {
    std::string name;
    std::string model;                 ///< "elastic", "johnson_cook" or "linear_hardening"
    ElasticConstants elastic;          ///< ρ0, E, ν (every model)
    std::optional<Material> material;  ///< the model, built and validated by the parser
    /// εmax of brittle bond failure by stretch (DESIGN §5, key `bond_stretch`); 0 = no bonds break.
    double bondStretch = 0.0;
    /// G0 [J/m²] of softening bonds (key `fracture_energy`; libgsph/forces/cohesive_bonds.hpp):
    /// > 0 makes the bonds that break by stretch soften; 0 = they break sharply.
    double fractureEnergy = 0.0;
    std::filesystem::path file;  ///< the material file it came from (empty: written inline)
    int line = 0;
};

/// One [[material]] table of `caseFile` (name + constants, or name + file).
MaterialSpec readMaterialTable(const std::filesystem::path& caseFile, const toml::table& table);

/// A material file; its name is the file's stem.
MaterialSpec readMaterialFile(const std::filesystem::path& path);

/// The material library folder: $GSPH_MATERIALS_DIR, else PREFIX/share/gsph/materials beside an
/// installed gsph-solve (PREFIX/bin), else the repository's materials/.
std::filesystem::path materialLibraryFolder();

/// Resolves `file` as described above; empty if nothing exists (`tried` lists the candidates).
std::filesystem::path resolveMaterialFile(const std::filesystem::path& caseFolder,
                                          const std::string& file,
                                          std::vector<std::filesystem::path>* tried = nullptr);

}  // namespace gsph::solver
