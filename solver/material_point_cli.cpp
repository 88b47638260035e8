// SPDX-License-Identifier: MIT
#include "material_point_cli.hpp"

#include <toml++/toml.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "material_config.hpp"
#include "toml_keys.hpp"

namespace gsph::solver {
namespace {

using Kind = LoadingPath::Kind;

LoadingPath readCompactPath(const std::string& file) {
    const toml::table root = parseTomlFile(file);
    const TomlKeys keys(file, root, "the path");
    keys.rejectUnknown(
        {"loading", "strain_rate", "final_strain", "temperature", "steps", "output_every"});
    LoadingPath path;
    const std::string loading = keys.text("loading", "");
    if (loading == "uniaxial_strain")
        path.kind = Kind::UniaxialStrain;
    else if (loading == "uniaxial_stress")
        path.kind = Kind::UniaxialStress;
    else if (loading == "simple_shear")
        path.kind = Kind::SimpleShear;
    else
        keys.fail("loading",
                  "'loading' must be \"uniaxial_strain\", \"uniaxial_stress\" or "
                  "\"simple_shear\"" +
                      (loading.empty() ? std::string() : ", got \"" + loading + "\""));
    path.strainRate = keys.number("strain_rate", TomlKeys::Sign::Any);
    if (path.strainRate == 0.0) keys.fail("strain_rate", "'strain_rate' must not be 0");
    path.finalStrain = keys.number("final_strain", TomlKeys::Sign::Any);
    if (!(path.finalStrain * path.strainRate > 0.0))
        keys.fail("final_strain", "'final_strain' must be non-zero, with the sign of strain_rate");
    if (keys.has("temperature"))
        path.temperature = keys.number("temperature", TomlKeys::Sign::Positive);
    path.steps = static_cast<int>(keys.integer("steps", path.steps, 1));
    path.outputEvery = static_cast<int>(keys.integer("output_every", 1, 1));
    return path;
}

// time, F_xx, F_xy, F_xz, F_yx, F_yy, F_yz, F_zx, F_zy, F_zz per row; '#' comments and one
// header line allowed.
LoadingPath readTablePath(const std::string& file, int substeps) {
    std::ifstream in(file);
    if (!in) throw InputError(file + ": cannot be read");
    LoadingPath path;
    path.kind = Kind::DeformationGradient;
    path.substeps = substeps;
    std::string line;
    bool header = false;
    for (int number = 1; std::getline(in, line); ++number) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        if (line.find_first_not_of(" \t\r,") == std::string::npos) continue;
        std::vector<double> values;
        std::stringstream cells(line);
        bool numeric = true;
        for (std::string cell; std::getline(cells, cell, ',');) {
            std::size_t used = 0;
            try {
                values.push_back(std::stod(cell, &used));
            } catch (const std::exception&) {
                numeric = false;
            }
            if (numeric && cell.find_first_not_of(" \t\r", used) != std::string::npos)
                numeric = false;
        }
        if (!numeric && !header && path.times.empty()) {
            header = true;  // the column names
            continue;
        }
        if (!numeric || values.size() != 10)
            throw InputError(file + ":" + std::to_string(number) +
                             ": expected 10 numbers: time, then F row by row (F_xx, F_xy, F_xz, "
                             "F_yx, ..., F_zz)");
        path.times.push_back(values[0]);
        Mat3 F;
        F << values[1], values[2], values[3], values[4], values[5], values[6], values[7], values[8],
            values[9];
        path.F.push_back(F);
    }
    return path;
}

}  // namespace

void addMaterialPointOptions(CLI::App& app, MaterialPointOptions& o) {
    CLI::Option* caseFile = app.get_option("case");
    caseFile->required(false);
    CLI::Option* material =
        app.add_option("--material-point", o.material,
                       "drive one material point of MATERIAL.toml along --path (writes a CSV; "
                       "-o names it, default stdout)")
            ->excludes(caseFile);
    app.add_option("--path", o.path,
                   "loading path: .toml (uniaxial_strain, uniaxial_stress, simple_shear) or "
                   ".csv (time, F_xx ... F_zz)")
        ->needs(material);
    app.add_option("--temperature", o.temperature, "initial temperature [K] of the point")
        ->needs(material);
    app.add_option("--substeps", o.substeps, "increments between two rows of a .csv path")
        ->needs(material)
        ->check(CLI::Range(1, 100000000));
    app.parse_complete_callback([&o, caseFile] {
        if (o.material.empty() && caseFile->count() == 0)
            throw CLI::RequiredError("a case file (or --material-point)");
        if (!o.material.empty() && o.path.empty()) throw CLI::RequiredError("--path");
    });
}

LoadingPath readLoadingPath(const std::filesystem::path& file, int substeps) {
    const std::string name = file.string();
    if (!std::filesystem::is_regular_file(file)) throw InputError(name + ": no such path file");
    if (file.extension() == ".toml") return readCompactPath(name);
    if (file.extension() == ".csv") return readTablePath(name, substeps);
    throw InputError(name + ": a path file is .toml (compact form) or .csv (table of F)");
}

void writeMaterialPointCsv(std::ostream& out, const std::vector<MaterialPointRecord>& rows) {
    out << "time,strain,sigma_xx,sigma_yy,sigma_zz,sigma_xy,sigma_yz,sigma_zx,pressure,von_mises,"
           "plastic_strain,temperature,damage,plastic_work\n";
    char line[512];
    for (const MaterialPointRecord& r : rows) {
        const Mat3& s = r.cauchy;
        const double p = -s.trace() / 3.0;
        const Mat3 dev = s + p * Mat3::Identity();
        std::snprintf(line, sizeof line,
                      "%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n",
                      r.time, r.strain, s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0), p,
                      std::sqrt(1.5 * dev.squaredNorm()), r.plasticStrain, r.temperature, r.damage,
                      r.plasticWork);
        out << line;
    }
}

int runMaterialPoint(const MaterialPointOptions& o, const std::string& output) {
    try {
        const MaterialSpec spec = readMaterialFile(o.material);
        LoadingPath path = readLoadingPath(o.path, o.substeps);
        if (o.temperature) path.temperature = o.temperature;
        std::vector<MaterialPointRecord> rows;
        try {
            rows = driveMaterialPoint(*spec.material, path);
        } catch (const InputError& e) {
            throw InputError(o.path + ": " + e.what());
        }
        if (output.empty()) {
            writeMaterialPointCsv(std::cout, rows);
            return 0;
        }
        std::ostringstream csv;
        writeMaterialPointCsv(csv, rows);
        writeTextAtomically(output, csv.str());
        const MaterialPointRecord& last = rows.back();
        std::printf(
            "gsph-solve: material point '%s' along %s: %zu rows -> %s (final strain %.4g, "
            "von Mises %.4g Pa, plastic strain %.4g, T %.1f K, damage %.3g)\n",
            spec.name.c_str(), o.path.c_str(), rows.size(), output.c_str(), last.strain,
            std::sqrt(1.5 *
                      (last.cauchy - last.cauchy.trace() / 3.0 * Mat3::Identity()).squaredNorm()),
            last.plasticStrain, last.temperature, last.damage);
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "gsph-solve: error: %s\n", e.what());
        return 1;
    }
}

}  // namespace gsph::solver
