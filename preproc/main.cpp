// SPDX-License-Identifier: MIT
// gsph-preproc: gmsh structured hex blocks → GSPH particle file (DESIGN §1, §2).
//
// Usage:
//   gsph-preproc INPUT -o PARTICLES.h5 [--set NAME=VALUE]... [--quiet]
//
// Sample runs:
//   gsph-preproc geometries/graded_bar.geo -o bar.h5
//   gsph-preproc geometries/taylor_bar.geo -o taylor.h5 --set refine=2
//   gmsh -3 geometries/notched_plate.geo -o plate.msh && gsph-preproc plate.msh -o plate.h5
//
// Description:
//   INPUT is a .geo (meshed in 3-D in-process by gmsh) or a .msh. Every gmsh volume must be a
//   structured hex block; blocks whose indices glue become one generalized space. One particle
//   per hex, at its parametric centre, with its exact volume and θ on a unit lattice. Physical
//   volumes become bodies, physical surfaces named particle sets. The file format is in
//   docs/formats.md. On error: one line on stderr naming the file and the fault, exit status 1,
//   and no output file.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <future>
#include <iostream>

#include "conversion.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "gmsh_input.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "summary.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

/// "NAME=VALUE" → (NAME, VALUE); NAME must be a gmsh identifier, VALUE a number.
std::pair<std::string, double> parseParameter(const std::string& text) {
    const std::size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    const bool nameOk = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                        std::all_of(name.begin(), name.end(),
                                    [](unsigned char c) { return std::isalnum(c) || c == '_'; });
    double value = 0.0;
    std::size_t used = 0;
    try {
        if (eq != std::string::npos) value = std::stod(text.substr(eq + 1), &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (!nameOk || eq == std::string::npos || used == 0 || eq + 1 + used != text.size() ||
        !std::isfinite(value)) {
        throw gsph::InputError("--set " + text + ": expected NAME=VALUE with a number VALUE");
    }
    return {name, value};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"gsph-preproc: gmsh structured hex blocks -> GSPH particle file"};
    std::string input, output;
    std::vector<std::string> parameters;
    bool quiet = false;
    app.add_option("input", input, "a .geo (meshed in 3-D in-process) or a .msh file")->required();
    app.add_option("-o,--output", output, "the particle file to write (HDF5)")->required();
    app.add_option("--set", parameters,
                   "NAME=VALUE: set a .geo parameter before parsing (overrides DefineConstant), "
                   "e.g. --set refine=2");
    app.add_flag("-q,--quiet", quiet, "print nothing but warnings and errors");
    app.set_version_flag("--version", gsph::kVersion);
    CLI11_PARSE(app, argc, argv);

    try {
        const auto start = Clock::now();
        // Hash the input for the provenance while gmsh reads it (a large .msh takes ~1 s).
        std::future<std::string> inputHash =
            std::async(std::launch::async, [&] { return gsph::sha256File(input); });
        gsph::preproc::MeshReadOptions options;
        std::string applied;
        for (const std::string& p : parameters) {
            options.parameters.push_back(parseParameter(p));
            applied += (applied.empty() ? "" : ",") + p;
        }
        std::vector<std::string> warnings;
        gsph::preproc::HexMesh mesh = gsph::preproc::readHexMesh(input, options, warnings);
        const auto read = Clock::now();

        gsph::preproc::Conversion conversion = gsph::preproc::convertHexMesh(mesh);
        mesh = {};
        warnings.insert(warnings.end(), conversion.warnings.begin(), conversion.warnings.end());
        const auto converted = Clock::now();

        conversion.particles.provenance = {"gsph-preproc",  gsph::kVersion, input,
                                           inputHash.get(), applied,        "SI"};
        gsph::writeParticleFile(output, conversion.particles);
        const auto written = Clock::now();

        for (const std::string& w : warnings) std::cerr << "gsph-preproc: warning: " << w << "\n";
        if (!quiet) {
            const gsph::preproc::Timings timings{seconds(start, read), seconds(read, converted),
                                                 seconds(converted, written),
                                                 seconds(start, written)};
            gsph::preproc::printSummary(std::cout, output, conversion.particles, conversion.stats,
                                        timings);
        }
        return 0;
    } catch (const std::exception& e) {
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        std::cerr << "gsph-preproc: error: " << message << "\n";
        return 1;
    }
}
