// SPDX-License-Identifier: MIT
// gsph-solve: runs a case.
//
// Usage:   gsph-solve CASE.toml [-o RUNDIR] [--particles FILE] [--threads N]
//          gsph-solve --material-point MATERIAL.toml --path PATH [-o OUT.csv] [--temperature T]
// Sample:  gsph-preproc geometries/graded_bar.geo -o run/bar/particles.h5
//          gsph-solve cases/graded_bar/case.toml -o run/bar
//          gsph-solve --material-point materials/ofhc_copper.toml
//                     --path materials/paths/uniaxial_stress_1e3.toml -o copper.csv
// Description: reads the case file (docs/case-format.md) and the particle file it names, runs
// the total Lagrangian GSPH solver, and writes snapshot_NNNNNN.h5, history.csv and run.log in
// RUNDIR (default: run/<case name>). Errors: one line on stderr, exit code 1.
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "case_config.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "material_point_cli.hpp"
#include "run.hpp"

namespace {

// run.log, written atomically; a failure is reported, not thrown (true: written).
bool writeLog(const std::filesystem::path& path, const std::vector<std::string>& lines) {
    try {
        gsph::writeAtomically(path, [&](const std::filesystem::path& temp) {
            std::ofstream out(temp);
            for (const std::string& line : lines) out << line << "\n";
            if (!out.flush()) throw gsph::IoError(path.string() + ": write failed (disk full?)");
        });
        return true;
    } catch (const gsph::Error& e) {
        std::fprintf(stderr, "gsph-solve: error: %s\n", e.what());
        return false;
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"gsph-solve: total Lagrangian GSPH solver"};
    app.set_version_flag("--version", gsph::kVersion);
    std::string casePath, runDir, particles;
    int threads = 0;
    app.add_option("case", casePath, "case file (TOML)")->required();
    app.add_option("-o,--output", runDir, "run folder (default: run/<case name>)");
    app.add_option("--particles", particles,
                   "particle file, instead of the case's [run] particles");
    app.add_option("--threads", threads, "OpenMP threads (default: OMP_NUM_THREADS or all cores)")
        ->check(CLI::Range(1, 1024));
    gsph::solver::MaterialPointOptions materialPoint;
    gsph::solver::addMaterialPointOptions(app, materialPoint);
    CLI11_PARSE(app, argc, argv);
    if (threads > 0) omp_set_num_threads(threads);
    if (materialPoint.requested()) return gsph::solver::runMaterialPoint(materialPoint, runDir);

    std::vector<std::string> log;
    gsph::solver::RunOptions options;
    try {
        gsph::solver::CaseConfig config = gsph::solver::readCaseFile(casePath);
        if (!particles.empty()) config.particles = particles;
        // Default run folder: run/<name of the case's folder>, or run/<case file stem>.
        const std::string caseName = config.caseFile.parent_path().filename().string();
        options.runDir = !runDir.empty() ? std::filesystem::path(runDir)
                         : caseName.empty() || caseName == "."
                             ? std::filesystem::path("run") / config.caseFile.stem()
                             : std::filesystem::path("run") / caseName;
        options.progress = isatty(STDERR_FILENO) != 0;
        options.log = [&](const std::string& line) {
            std::printf("%s\n", line.c_str());
            log.push_back(line);
        };
        options.log("gsph-solve " + std::string(gsph::kVersion) + ": " + casePath + " -> " +
                    options.runDir.string() + " (" + std::to_string(omp_get_max_threads()) +
                    " threads)");
        gsph::solver::runCase(config, options);
    } catch (const gsph::Error& e) {
        std::fprintf(stderr, "%sgsph-solve: error: %s\n", options.progress ? "\n" : "", e.what());
        log.push_back(std::string("error: ") + e.what());
        // The run folder may not exist (the case file was refused): then there is no log.
        if (!options.runDir.empty() && std::filesystem::is_directory(options.runDir))
            writeLog(options.runDir / "run.log", log);
        return 1;
    }
    if (!writeLog(options.runDir / "run.log", log)) return 1;
    return 0;
}
