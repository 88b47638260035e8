// SPDX-License-Identifier: MIT
// gsph-preproc: gmsh structured hex (or 2-D quad) blocks → GSPH particle file (DESIGN §1, §2).
//
// Usage:
//   gsph-preproc INPUT -o PARTICLES.h5 [--set NAME=VALUE]... [--priority VOLUME=N]...
//                [--overset-kappa K] [--lattice H] [--quiet]
//
// Sample runs:
//   gsph-preproc geometries/graded_bar.geo -o bar.h5
//   gsph-preproc geometries/taylor_bar.geo -o taylor.h5 --set refine=2
//   gmsh -3 geometries/notched_plate.geo -o plate.msh && gsph-preproc plate.msh -o plate.h5
//   gsph-preproc geometries/two_blocks.geo -o blocks.h5 --set overlap=2 --priority 1=1
//   gsph-preproc geometries/taylor_bar.geo -o uniform.h5 --lattice 0.475e-3
//   gsph-preproc geometries/taylor_bar_axisymmetric.geo -o taylor_rz.h5
//
// Description:
//   INPUT is a .geo (meshed in 3-D in-process by gmsh) or a .msh. Every gmsh volume must be a
//   structured hex block; blocks whose indices glue become one generalized space. One particle
//   per hex, at its parametric centre, with its exact volume and θ on a unit lattice. Physical
//   volumes become bodies, physical surfaces named particle sets. A body of several spaces is an
//   overset layout (DESIGN §6): where spaces overlap, the one of higher priority (--priority,
//   default: the finer one) keeps its particles and the other's are cut; particles within
//   2·K·Δθ of another space's particles become transient there (--overset-kappa K, default
//   1.5). --lattice H instead fills each body with the uniform Cartesian lattice of standard SPH
//   (spacing ≈ H, sites inside the meshed region: uniform_lattice.hpp), for comparisons. The
//   file format is in docs/formats.md. A 2-D mesh (a .geo with surfaces and no volumes, meshed
//   in 2-D; a .msh of quadrangles) of structured quad blocks in the plane z = 0 gives a 2-D
//   file: physical surfaces are its bodies, physical curves its sets. On error: one line on stderr
//   naming the file and the fault, exit status 1 (4 if the output could not be written: disk full,
//   quota), and no output file (an existing one is kept). gmsh runs in a child process, so a crash
//   inside gmsh is such an error too.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <future>
#include <iostream>
#include <map>

#include "conversion.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "gmsh_input.hpp"
#include "io/atomic_file.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "mesh_process.hpp"
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

/// "VOLUME=N" → {VOLUME, N}; VOLUME a gmsh volume tag or physical volume group name.
gsph::preproc::PriorityRule parsePriority(const std::string& text) {
    const std::size_t eq = text.rfind('=');
    gsph::preproc::PriorityRule rule;
    std::size_t used = 0;
    try {
        if (eq != std::string::npos && eq > 0) {
            rule.volume = text.substr(0, eq);
            rule.priority = std::stoi(text.substr(eq + 1), &used);
        }
    } catch (const std::exception&) {
        used = 0;
    }
    if (rule.volume.empty() || used == 0 || eq + 1 + used != text.size()) {
        throw gsph::InputError("--priority " + text +
                               ": expected VOLUME=N (a gmsh volume tag or physical volume group "
                               "name, and an integer)");
    }
    return rule;
}

}  // namespace

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) is a failed write with its own message, not a kill.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"gsph-preproc: gmsh structured hex (or 2-D quad) blocks -> GSPH particle file"};
    std::string input, output;
    std::vector<std::string> parameters;
    bool quiet = false;
    app.add_option("input", input,
                   "a .geo (meshed in-process: in 3-D, or in 2-D if it has surfaces but no "
                   "volumes) or a .msh file")
        ->required();
    app.add_option("-o,--output", output, "the particle file to write (HDF5)")->required();
    app.add_option("--set", parameters,
                   "NAME=VALUE: set a .geo parameter before parsing (overrides DefineConstant), "
                   "e.g. --set refine=2");
    std::vector<std::string> priorities;
    app.add_option("--priority", priorities,
                   "VOLUME=N: priority of a gmsh volume (tag) or physical volume group (name) "
                   "where spaces overlap; the higher keeps its particles (default 0; at equal "
                   "priority the finer space wins)");
    gsph::preproc::ConversionOptions convertOptions;
    app.add_option("--overset-kappa", convertOptions.oversetKappa,
                   "K: particles within 2*K*dtheta of another space's particles are transient "
                   "there (default 1.5: enough for runs with kappa <= K)");
    const std::map<std::string, gsph::preproc::TransientRule> transientRules = {
        {"auto", gsph::preproc::TransientRule::Automatic},
        {"map", gsph::preproc::TransientRule::Map},
        {"lattice", gsph::preproc::TransientRule::Lattice}};
    app.add_option("--transients", convertOptions.transients,
                   "RULE: how a particle near another space gets its theta there: 'map' locates "
                   "it in that space's isoparametric map extended past its boundary; 'lattice' "
                   "continues that space's lattice across the block faces the two share; 'auto' "
                   "(default) the map, and the lattice for a pair of spaces where the map folds")
        ->transform(CLI::CheckedTransformer(transientRules, CLI::ignore_case));
    app.add_option("--lattice", convertOptions.latticeSpacing,
                   "H [m]: write the uniform Cartesian layout of standard SPH instead (spacing H, "
                   "adjusted per axis to tile each body's bounding box; the sites inside the "
                   "mesh), for comparison with the hex layout");
    app.add_flag("-q,--quiet", quiet, "print nothing but warnings and errors");
    app.set_version_flag("--version", gsph::kVersion);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 1;  // --help, --version: 0; a bad option: 1
    }

    try {
        const auto start = Clock::now();
        std::error_code ec;
        if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
            throw gsph::InputError(output + ": is the input file itself; give another -o");
        gsph::removeStaleTemporaries(std::filesystem::absolute(output).parent_path());
        // Hash the input for the provenance while gmsh reads it (a large .msh takes ~1 s).
        std::future<std::string> inputHash =
            std::async(std::launch::async, [&] { return gsph::sha256File(input); });
        gsph::preproc::MeshReadOptions options;
        std::string applied;
        for (const std::string& p : parameters) {
            options.parameters.push_back(parseParameter(p));
            applied += (applied.empty() ? "" : ",") + p;
        }
        for (const std::string& p : priorities)
            convertOptions.priorities.push_back(parsePriority(p));
        std::vector<std::string> warnings;
        gsph::preproc::HexMesh mesh = gsph::preproc::readHexMeshInChild(input, options, warnings);
        const auto read = Clock::now();

        if (!quiet) {
            convertOptions.onSpaces = [&](const gsph::ParticleFile& particles,
                                          const gsph::preproc::ConversionStats& stats) {
                gsph::preproc::printSpaces(std::cout, input, applied, output, particles, stats);
            };
        }
        gsph::preproc::Conversion conversion = gsph::preproc::convertHexMesh(mesh, convertOptions);
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
            gsph::preproc::printSummary(std::cout, conversion.particles, conversion.stats, timings);
        }
        return 0;
    } catch (const std::exception& e) {
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        std::cerr << "gsph-preproc: error: " << message << "\n";
        return dynamic_cast<const gsph::WriteError*>(&e) ? 4 : 1;
    }
}
