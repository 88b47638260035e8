// SPDX-License-Identifier: MIT
// gsph-post: turns a run folder into ParaView files and pictures.
//
// Usage:   gsph-post RUNDIR [-o OUTDIR] [--field von_mises|pressure|displacement|velocity|J]
//                    [--no-pictures]
// Sample:  gsph-post run/graded_bar
// Description: writes OUTDIR (default RUNDIR/post) with run.pvd + snapshot_NNNNNN.vtu (open
// run.pvd in ParaView), final_<field>.png (the last snapshot, deformed, coloured by the field)
// and history.png (the energies of history.csv). Pictures need an X server: without DISPLAY
// gsph-post re-runs itself under `xvfb-run -a` (package xvfb). Errors: one line, exit code 1.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "core/version.hpp"
#include "io/snapshot.hpp"
#include "pictures.hpp"
#include "vtk_output.hpp"

namespace fs = std::filesystem;

namespace {

// Re-executes this command under xvfb-run when pictures need an X server and none is set.
void ensureDisplay(int argc, char** argv) {
    const char* display = std::getenv("DISPLAY");
    if ((display && *display) || std::getenv("GSPH_POST_UNDER_XVFB")) return;
    setenv("GSPH_POST_UNDER_XVFB", "1", 1);
    std::vector<char*> args = {const_cast<char*>("xvfb-run"), const_cast<char*>("-a")};
    for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
    args.push_back(nullptr);
    execvp("xvfb-run", args.data());
    throw gsph::Error(
        "no X display for the pictures and xvfb-run is not installed (apt-get install xvfb), or "
        "use --no-pictures");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"gsph-post: ParaView files and pictures of a GSPH run"};
    app.set_version_flag("--version", gsph::kVersion);
    std::string runDir, outDir, field = "von_mises";
    bool noPictures = false;
    app.add_option("rundir", runDir, "run folder written by gsph-solve")->required();
    app.add_option("-o,--output", outDir, "output folder (default: RUNDIR/post)");
    app.add_option("--field", field, "field of the picture")
        ->check(CLI::IsMember({"von_mises", "pressure", "displacement", "velocity", "J"}));
    app.add_flag("--no-pictures", noPictures, "write only the ParaView files");
    CLI11_PARSE(app, argc, argv);
    try {
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
        if (!noPictures) ensureDisplay(argc, argv);
        const fs::path out = outDir.empty() ? fs::path(runDir) / "post" : fs::path(outDir);
        fs::create_directories(out);
        std::vector<std::pair<double, std::string>> series;
        gsph::Snapshot last;
        for (const fs::path& p : snapshots) {
            last = gsph::readSnapshot(p);
            const std::string vtu = p.stem().string() + ".vtu";
            gsph::post::writeVtu(out / vtu, last);
            series.emplace_back(last.time, vtu);
        }
        gsph::post::writePvd(out / "run.pvd", series);
        std::printf("gsph-post: %zu snapshots -> %s (open run.pvd in ParaView)\n", snapshots.size(),
                    (out / "run.pvd").c_str());
        if (!noPictures) {
            const fs::path picture = out / ("final_" + field + ".png");
            gsph::post::renderSnapshot(last, field, picture);
            std::printf("gsph-post: picture %s\n", picture.c_str());
            const fs::path history = fs::path(runDir) / "history.csv";
            if (fs::exists(history)) {
                gsph::post::plotHistory(history, out / "history.png");
                std::printf("gsph-post: plot %s\n", (out / "history.png").c_str());
            }
        }
    } catch (const gsph::Error& e) {
        std::fprintf(stderr, "gsph-post: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
