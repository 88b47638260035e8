// SPDX-License-Identifier: MIT
// post_bench_run: a synthetic run folder for timing gsph-post (docs/performance.md).
//
// Usage:   post_bench_run OUTDIR [--cells N] [--snapshots K]
// Sample:  post_bench_run /tmp/bench1e5 --cells 46 --snapshots 50 && time gsph-post /tmp/bench1e5
// Description: a unit cube of N³ particles (κ = 1.2) through the library's snapshot writer,
// K snapshots of a shear that grows with time, with the bonds crossing a plane that sweeps
// from z = 0.2 to z = 0.8 broken (so every snapshot has a crack surface to build).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "io/snapshot.hpp"
#include "support/lattice_fixtures.hpp"

int main(int argc, char** argv) {
    CLI::App app{"post_bench_run: synthetic snapshots for timing gsph-post"};
    std::string out;
    int cells = 46, snapshots = 50;
    app.add_option("outdir", out, "run folder to write")->required();
    app.add_option("--cells", cells, "particles per side");
    app.add_option("--snapshots", snapshots, "number of snapshots");
    CLI11_PARSE(app, argc, argv);
    using namespace gsph;
    const auto t0 = std::chrono::steady_clock::now();
    const AxisGrading uniform;
    const Reference ref = testing::builtReference(
        gradedBoxMap(Vec3(1, 1, 1), {uniform, uniform, uniform}), 3, {cells, cells, cells});
    std::filesystem::create_directories(out);
    State s = State::atRest(ref.X, ref.pairs.neighbor.size());
    for (int k = 0; k < snapshots; ++k) {
        const double phase = snapshots > 1 ? static_cast<double>(k) / (snapshots - 1) : 0.0;
        s.time = 1e-6 * k;
        s.step = 100L * k;
        Mat3 F = Mat3::Identity();
        F(0, 2) = 0.05 * phase;
        const double cut = 0.2 + 0.6 * phase;
        for (std::size_t a = 0; a < s.x.size(); ++a) {
            s.x[a] = F * ref.X[a];
            s.F[a] = F;
            s.v[a] = Vec3(phase * ref.X[a][2], 0.0, 0.0);
            s.cauchy[a] = 1e8 * phase * (Mat3() << 0, 0, 1, 0, 0, 0, 1, 0, 0).finished();
            s.plasticStrain[a] = 0.01 * phase * ref.X[a][0];
        }
        std::fill(s.bondIntact.begin(), s.bondIntact.end(), std::uint8_t{1});
        for (Index a = 0; a < ref.size(); ++a)
            for (Index p = ref.pairs.begin(a); p < ref.pairs.end(a); ++p) {
                const Index b = ref.pairs.neighbor[static_cast<std::size_t>(p)];
                const double za = ref.X[static_cast<std::size_t>(a)][2] - cut;
                const double zb = ref.X[static_cast<std::size_t>(b)][2] - cut;
                if (za * zb < 0.0) s.bondIntact[static_cast<std::size_t>(p)] = 0;
            }
        char name[64];
        std::snprintf(name, sizeof name, "snapshot_%06d.h5", k);
        writeSnapshot(std::filesystem::path(out) / name, ref, s, Provenance{});
    }
    std::printf("post_bench_run: %d snapshots of %d particles in %s (%.1f s)\n", snapshots,
                static_cast<int>(ref.size()), out.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return 0;
}
