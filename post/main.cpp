// SPDX-License-Identifier: MIT
// gsph-post: turns a run folder into ParaView files and pictures.
//
// Usage:   gsph-post RUNDIR [-o OUTDIR] [--field NAME] [--times T1,T2,...] [--size W,H]
//                    [--particles FILE] [--no-pictures] [--no-cracks] [--no-solid]
//                    [--revolve N]
// Sample:  gsph-post run/graded_bar
//          gsph-post run/graded_bar --field plastic_strain --times 1e-5,3e-5
//          gsph-post run/axisymmetric_bar --revolve 24
// Description: writes OUTDIR (default RUNDIR/post) with
//   run.pvd + snapshot_NNNNNN.vtu    particles with every field (open run.pvd in ParaView),
//   solid.pvd + solid_NNNNNN.vtm     the solid: the hexahedral cells of every space (one
//     + solid_NNNNNN_sS.vtu          .vtu per space S) with the fields as cell data (Slice,
//                                    Clip, surface rendering); a 2-D run (plane strain or
//                                    axisymmetric) gives its section instead: one
//                                    quadrilateral per particle in the x-y plane; needs the
//                                    run's particle file (--particles, else the one
//                                    checkpoint.h5 names, else RUNDIR/particles.h5),
//   solid_revolved.pvd + solid_revolved_NNNNNN.vtm + _sS.vtu   with --revolve N (N ≥ 3, an
//                                    axisymmetric run): the section swept about the y axis
//                                    into N sectors of hexahedra (wedges at the axis), each
//                                    with its particle's fields, vectors and tensors turned
//                                    into the sector (a 3-D particle file is an error),
//   cracks.pvd + crack_NNNNNN.vtp    crack surfaces (Voronoi facets of the broken bonds),
//   FIELD_NNNNNN.png                 the deformed solid (or particles without the particle
//                                    file) coloured by FIELD at each of --times
//                                    (the snapshot nearest to each time), or final_FIELD.png
//                                    (the last snapshot) without --times,
//   history.png, momentum.png        energies and momentum of history.csv.
// Pictures need an X server: without DISPLAY gsph-post re-runs itself under `xvfb-run -a`
// (package xvfb). Errors: one line naming the file; exit code 1 (bad input, a bad option), 4
// (an output file or folder could not be written: every file it would replace is kept).
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/version.hpp"
#include "crack_surface.hpp"
#include "hex_solid.hpp"
#include "io/atomic_file.hpp"
#include "io/particle_file.hpp"
#include "io/snapshot.hpp"
#include "pictures.hpp"
#include "vtk_output.hpp"

namespace fs = std::filesystem;

namespace {

bool haveDisplay() {
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}

// Runs the pictures in a child `gsph-post --pictures-of …` under xvfb-run. Debian's VTK is an
// X11 build; the X connection of a fresh Xvfb sometimes fails on a loaded machine (VTK then
// aborts: measured 1 in 4 with four runs at once), so a child that dies that way is retried.
void picturesUnderXvfb(const char* self, const std::vector<std::string>& childArgs) {
    constexpr int kAttempts = 3;
    for (int attempt = 1; attempt <= kAttempts; ++attempt) {
        // xvfb-run -a starts its search for a free display at 99: concurrent runs race for the
        // same number. Start at a number of our own (-n before -a: -a searches from it).
        std::string first = std::to_string(100 + (getpid() * 7 + attempt) % 30000);
        std::vector<std::string> words = {"xvfb-run", "-n", first, "-a", self};
        words.insert(words.end(), childArgs.begin(), childArgs.end());
        std::vector<char*> args;
        for (std::string& w : words) args.push_back(w.data());
        args.push_back(nullptr);
        std::fflush(stdout);
        const pid_t child = fork();
        if (child < 0) throw gsph::Error("cannot start xvfb-run for the pictures (fork failed)");
        if (child == 0) {
            execvp("xvfb-run", args.data());
            std::fprintf(stderr,
                         "gsph-post: error: no X display for the pictures and xvfb-run is not "
                         "installed (apt-get install xvfb), or use --no-pictures\n");
            _exit(1);
        }
        int status = 0;
        if (waitpid(child, &status, 0) < 0) throw gsph::Error("lost the pictures' xvfb-run");
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
        if (WIFEXITED(status) && WEXITSTATUS(status) == 1)  // the child said why
            throw gsph::Error("the pictures failed (see above)");
        std::fprintf(stderr, "gsph-post: the X server of the pictures failed (status %d)%s\n",
                     WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
                     attempt < kAttempts ? ", trying again" : "");
    }
    throw gsph::Error("no picture: the X server failed " + std::to_string(kAttempts) + " times");
}

std::vector<fs::path> snapshotFiles(const std::string& runDir) {
    if (!fs::is_directory(runDir)) throw gsph::InputError(runDir + ": no such run folder");
    std::vector<fs::path> snapshots;
    for (const fs::directory_entry& e : fs::directory_iterator(runDir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("snapshot_", 0) == 0 && e.path().extension() == ".h5")
            snapshots.push_back(e.path());
    }
    std::sort(snapshots.begin(), snapshots.end());
    if (snapshots.empty())
        throw gsph::InputError(runDir + ": no snapshot_*.h5 files (did gsph-solve run?)");
    return snapshots;
}

// True if the points span three dimensions (a 2-D run lies in one plane: no crack surfaces).
bool spansThreeDimensions(const std::vector<gsph::Vec3>& X) {
    gsph::Vec3 lo = gsph::Vec3::Constant(1e300), hi = gsph::Vec3::Constant(-1e300);
    for (const gsph::Vec3& p : X) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const gsph::Vec3 extent = hi - lo;
    return X.size() >= 4 && extent.minCoeff() > 1e-9 * extent.maxCoeff();
}

// Snapshot index nearest to each requested time (by the snapshots' own /time).
std::vector<std::size_t> nearestSnapshots(const std::vector<double>& times,
                                          const std::vector<double>& wanted) {
    std::vector<std::size_t> out;
    for (double t : wanted) {
        std::size_t best = 0;
        for (std::size_t k = 1; k < times.size(); ++k)
            if (std::abs(times[k] - t) < std::abs(times[best] - t)) best = k;
        out.push_back(best);
    }
    return out;
}

// The run's solid (hex_solid.hpp) from its particle file, and the names for the field data.
struct RunSolid {
    std::unique_ptr<gsph::post::HexSolid> solid;
    gsph::post::RunLabels labels;
    fs::path path;       // the particle file
    std::string source;  // and how it was found
};

// Builds the solid for the snapshots' reference positions X. `given`: --particles (a failure
// to use it is an error); otherwise a particle file that is not found or does not fit leaves
// the solid out, with one line that says why.
RunSolid loadSolid(const fs::path& runDir, const fs::path& given,
                   const std::vector<gsph::Vec3>& X) {
    RunSolid run;
    const gsph::post::ParticleFileLocation where = gsph::post::locateParticleFile(runDir, given);
    if (!where.path) {
        if (!given.empty()) throw gsph::InputError(where.why);
        std::printf("gsph-post: no solid, only the particles: %s\n", where.why.c_str());
        return run;
    }
    try {
        const gsph::ParticleFile file = gsph::readParticleFileIsolated(*where.path);
        run.solid = std::make_unique<gsph::post::HexSolid>(file, X, where.path->string());
        for (const gsph::BodyInfo& b : file.bodies) run.labels.bodyNames.push_back(b.name);
        for (const auto& [name, members] : file.sets) run.labels.setNames.push_back(name);
        run.path = *where.path;
        run.source = where.path->string() + " (" + where.why + ")";
    } catch (const gsph::Error& e) {
        if (!given.empty()) throw;
        std::printf("gsph-post: no solid, only the particles: %s\n", e.what());
    }
    return run;
}

// The pictures (needs an X server): each snapshot of `pictured` coloured by `field`, named
// final_FIELD.png if `final`, else FIELD_NNNNNN.png; then the plots of history.csv. The body is
// drawn as its solid when `particles` names the run's particle file, else as particles.
void renderPictures(const std::vector<std::string>& pictured, bool final, const std::string& field,
                    const fs::path& runDir, const fs::path& out, const std::vector<int>& size,
                    const fs::path& particles) {
    RunSolid run;
    for (const std::string& file : pictured) {
        const gsph::Snapshot snap = gsph::readSnapshotIsolated(file);
        if (!particles.empty() && !run.solid) run = loadSolid(runDir, particles, snap.X);
        const std::string stem = fs::path(file).stem().string();
        const fs::path picture =
            out / (final ? "final_" + field + ".png"
                         : field + "_" + stem.substr(std::string("snapshot_").size()) + ".png");
        gsph::post::renderSnapshot(snap, field, picture, size[0], size[1], run.solid.get());
        std::printf("gsph-post: picture %s (t = %.6g s)\n", picture.c_str(), snap.state.time);
    }
    const fs::path historyCsv = runDir / "history.csv";
    if (!fs::exists(historyCsv)) return;
    const gsph::post::HistoryTable history = gsph::post::readHistory(historyCsv);
    const std::vector<std::string> energies = {
        "kinetic_energy",     "internal_energy", "plastic_work",
        "damage_dissipation", "fracture_energy", "hourglass_work",
        "viscous_work",       "external_work",   "total_energy"};
    const int plotWidth = size[0] * 5 / 6, plotHeight = size[1] * 3 / 4;
    if (!gsph::post::plotHistory(history, energies, "energy [J]", out / "history.png", plotWidth,
                                 plotHeight))
        throw gsph::InputError(historyCsv.string() +
                               ": not a gsph history (no time and energy columns)");
    std::printf("gsph-post: plot %s\n", (out / "history.png").c_str());
    if (gsph::post::plotHistory(history, {"momentum_x", "momentum_y", "momentum_z"},
                                "momentum [kg m/s]", out / "momentum.png", plotWidth, plotHeight))
        std::printf("gsph-post: plot %s\n", (out / "momentum.png").c_str());
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// CPU time of the process (all threads) [s]: the figure that a shared machine does not disturb.
double cpuSeconds() {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

}  // namespace

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) is a failed write with its own message, not a kill.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"gsph-post: ParaView files and pictures of a GSPH run"};
    app.set_version_flag("--version", gsph::kVersion);
    std::string runDir, outDir, field = "von_mises", particlesOption;
    std::vector<double> times;
    bool noPictures = false, noCracks = false, noSolid = false;
    int revolve = 0;
    app.add_option("rundir", runDir, "run folder written by gsph-solve")->required();
    app.add_option("-o,--output", outDir, "output folder (default: RUNDIR/post)");
    app.add_option("--field", field, "field of the pictures")
        ->check(CLI::IsMember(gsph::post::scalarFieldNames()));
    app.add_option("--times", times,
                   "times [s] of the pictures, comma-separated (the nearest snapshots; default: "
                   "the last)")
        ->delimiter(',');
    std::vector<int> size = {1200, 800};
    app.add_option("--size", size,
                   "width,height of the body's pictures in pixels (plots: 5/6 and 3/4 of it)")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(64, 8192));
    app.add_flag("--no-pictures", noPictures, "write only the ParaView files");
    app.add_flag("--no-cracks", noCracks, "write no crack surfaces");
    app.add_option("--particles", particlesOption,
                   "the run's particle file, for the solid (default: the one checkpoint.h5 "
                   "names, else RUNDIR/particles.h5)");
    auto* noSolidFlag =
        app.add_flag("--no-solid", noSolid, "write no solid (hexahedra), only the particles");
    app.add_option("--revolve", revolve,
                   "an axisymmetric run's section swept about the y axis into N sectors "
                   "(solid_revolved.pvd)")
        ->check(CLI::Range(3, 3600))
        ->excludes(noSolidFlag);
    // Internal: the pictures' child process under xvfb-run (picturesUnderXvfb).
    std::vector<std::string> picturesOf;
    bool finalPicture = false;
    app.add_option("--pictures-of", picturesOf)->group("");
    app.add_flag("--final-picture", finalPicture)->group("");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 1;  // --help, --version: 0; a bad option: 1
    }
    try {
        const fs::path out = outDir.empty() ? fs::path(runDir) / "post" : fs::path(outDir);
        if (!picturesOf.empty()) {
            renderPictures(picturesOf, finalPicture, field, runDir, out, size,
                           noSolid ? fs::path() : fs::path(particlesOption));
            return 0;
        }
        const std::vector<fs::path> snapshots = snapshotFiles(runDir);
        std::error_code made;
        fs::create_directories(out, made);
        if (made)
            throw gsph::WriteError(out.string() + ": cannot create the output folder (" +
                                   made.message() + ")");
        gsph::removeStaleTemporaries(out);
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = cpuSeconds();

        std::vector<std::pair<double, std::string>> series, crackSeries, solidSeries,
            revolvedSeries;
        RunSolid solid;                                     // built at the first snapshot
        std::unique_ptr<gsph::post::CrackSurfaces> cracks;  // the run's Delaunay, built once
        bool cracksPossible = !noCracks;
        double crackSetup = 0.0, crackArea = 0.0, crackProjected = 0.0;
        std::size_t crackPolygons = 0, unmatched = 0;
        std::vector<double> snapshotTimes;
        gsph::Snapshot last;
        for (std::size_t k = 0; k < snapshots.size(); ++k) {
            const fs::path& p = snapshots[k];
            gsph::Snapshot snap = gsph::readSnapshotIsolated(p);
            if (k > 0 && snap.size() != last.size())
                throw gsph::InputError(p.string() + ": " + std::to_string(snap.size()) +
                                       " particles, the run's first snapshot has " +
                                       std::to_string(last.size()));
            const std::string stem = p.stem().string();
            const std::string vtu = stem + ".vtu";
            if (k == 0 && !noSolid) {
                solid = loadSolid(runDir, particlesOption, snap.X);
                if (revolve > 0) {
                    if (!solid.solid)
                        throw gsph::InputError(runDir +
                                               ": --revolve needs the run's particle file (no "
                                               "solid, see above); pass --particles FILE");
                    gsph::post::requireRevolvableSection(*solid.solid, revolve,
                                                         solid.path.string());
                    if (!snap.axisymmetric)
                        throw gsph::InputError(
                            p.string() +
                            ": --revolve sweeps an axisymmetric run's section, and "
                            "this run is not axisymmetric ([run] dimension)");
                }
            }
            // A planar run has no crack surfaces to draw: say so once, write no empty ones.
            if (k == 0 && cracksPossible && !spansThreeDimensions(snap.X)) {
                std::printf("gsph-post: a planar (2-D) run: no crack surfaces\n");
                cracksPossible = false;
            }
            gsph::post::writeVtu(out / vtu, snap, solid.labels);
            series.emplace_back(snap.state.time, vtu);
            if (solid.solid) {
                const std::string vtm =
                    "solid_" + stem.substr(std::string("snapshot_").size()) + ".vtm";
                gsph::post::writeSolid(out / vtm, *solid.solid, snap, solid.labels);
                solidSeries.emplace_back(snap.state.time, vtm);
                if (revolve > 0) {
                    const std::string revolved =
                        "solid_revolved_" + stem.substr(std::string("snapshot_").size()) + ".vtm";
                    gsph::post::writeSolid(out / revolved, *solid.solid, snap, solid.labels,
                                           revolve);
                    revolvedSeries.emplace_back(snap.state.time, revolved);
                }
            }
            if (cracksPossible) {
                gsph::post::CrackSurface surface;
                if (!snap.brokenBonds.empty()) {
                    if (!cracks) {
                        const double t0 = cpuSeconds();
                        try {
                            cracks = std::make_unique<gsph::post::CrackSurfaces>(snap.X, snap.body);
                        } catch (const gsph::InputError& e) {
                            std::printf("gsph-post: no crack surfaces: %s\n", e.what());
                            cracksPossible = false;
                        }
                        crackSetup = cpuSeconds() - t0;
                    }
                    if (cracks) surface = cracks->surface(snap);
                }
                if (cracksPossible) {
                    const std::string vtp =
                        "crack_" + stem.substr(std::string("snapshot_").size()) + ".vtp";
                    gsph::post::writeVtp(out / vtp, surface);
                    crackSeries.emplace_back(snap.state.time, vtp);
                    crackArea = surface.totalReferenceArea();
                    crackProjected = surface.totalProjectedArea();
                    crackPolygons = surface.polygons();
                    unmatched = surface.brokenBondsWithoutFacet;
                }
            }
            snapshotTimes.push_back(snap.state.time);
            last = std::move(snap);
        }
        gsph::post::writePvd(out / "run.pvd", series);
        std::printf("gsph-post: %zu snapshots of %d particles -> %s (open run.pvd in ParaView)\n",
                    snapshots.size(), static_cast<int>(last.size()), (out / "run.pvd").c_str());
        if (solid.solid) {
            gsph::post::writePvd(out / "solid.pvd", solidSeries);
            const gsph::post::HexSolid& s = *solid.solid;
            const double particleVolume = s.particleVolume(last);
            const double solidVolume = s.currentVolume(last);
            const bool planar = s.dimension() == 2;
            std::printf(
                "gsph-post: solid -> %s (open solid.pvd in ParaView): %zu spaces, %zu %s, "
                "nodes %s %s\n",
                (out / "solid.pvd").c_str(), s.pieces().size(), s.cells(),
                planar ? "quadrilaterals (a 2-D run's section)" : "hexahedra",
                s.estimatedNodes() ? "estimated from the particles: no /spaces/nodes in" : "from",
                solid.source.c_str());
            // A 2-D run's section: areas, against Σ V det F of F's in-plane block.
            const char* unit = planar ? "m²" : "m³";
            std::printf(
                "gsph-post: solid %s: reference %.9g %s (Σ V %.9g %s), last snapshot %.9g %s "
                "(Σ V %s %.9g %s, %+.3g %%)\n",
                planar ? "area" : "volume", s.referenceVolume(), unit, s.particleVolume(), unit,
                solidVolume, unit, planar ? "det F_xy" : "J", particleVolume, unit,
                100.0 * (solidVolume - particleVolume) / particleVolume);
            if (revolve > 0) {
                gsph::post::writePvd(out / "solid_revolved.pvd", revolvedSeries);
                std::size_t cells = 0;
                double volume = 0.0, pappus = 0.0;
                for (const gsph::post::SolidPiece& piece : s.pieces()) {
                    const std::vector<gsph::Vec3> x = s.currentNodes(piece, last);
                    const gsph::post::RevolvedCells r =
                        gsph::post::revolveSection(piece, x, revolve);
                    cells += r.cells();
                    volume += r.volume();
                    pappus += gsph::post::solidOfRevolutionVolume(piece, x);
                }
                std::printf(
                    "gsph-post: revolved solid -> %s: %d sectors, %zu cells; last snapshot %.9g "
                    "m³ (the section's solid of revolution %.9g m³: the %d-gon's %.6f)\n",
                    (out / "solid_revolved.pvd").c_str(), revolve, cells, volume, pappus, revolve,
                    volume / pappus);
            }
        }
        if (cracksPossible) {
            gsph::post::writePvd(out / "cracks.pvd", crackSeries);
            std::printf(
                "gsph-post: crack surfaces -> %s: last snapshot %zu facets, reference area "
                "%.6g m², projected %.6g m² (%zu broken bonds are no Delaunay edge)",
                (out / "cracks.pvd").c_str(), crackPolygons, crackArea, crackProjected, unmatched);
            if (cracks)
                std::printf("; Delaunay of %zu particles + %zu ghosts, body by body, in %.2f s CPU",
                            static_cast<std::size_t>(last.size()), cracks->ghosts(), crackSetup);
            if (cracks && cracks->flatBodies() > 0)
                std::printf("; %zu flat bodies (not spanning three dimensions) have none",
                            cracks->flatBodies());
            std::printf("\n");
        }
        std::printf("gsph-post: ParaView files in %.2f s (%.2f s CPU)\n", seconds(start),
                    cpuSeconds() - cpuStart);
        if (!noPictures) {
            std::vector<std::string> pictured;
            if (times.empty()) pictured.push_back(snapshots.back().string());
            for (std::size_t k : nearestSnapshots(snapshotTimes, times))
                pictured.push_back(snapshots[k].string());
            if (haveDisplay()) {
                renderPictures(pictured, times.empty(), field, runDir, out, size,
                               solid.solid ? solid.path : fs::path());
            } else {
                std::vector<std::string> child = {
                    runDir,
                    "-o",
                    out.string(),
                    "--field",
                    field,
                    "--size",
                    std::to_string(size[0]) + "," + std::to_string(size[1])};
                if (times.empty()) child.push_back("--final-picture");
                if (solid.solid) {
                    child.push_back("--particles");
                    child.push_back(solid.path.string());
                } else {
                    child.push_back("--no-solid");
                }
                for (const std::string& p : pictured) {
                    child.push_back("--pictures-of");
                    child.push_back(p);
                }
                picturesUnderXvfb(fs::read_symlink("/proc/self/exe").c_str(), child);
            }
        }
    } catch (const gsph::WriteError& e) {
        std::fprintf(stderr, "gsph-post: error: %s\n", e.what());
        return 4;
    } catch (const std::exception& e) {  // gsph::Error, a folder that cannot be made, ...
        std::fprintf(stderr, "gsph-post: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
