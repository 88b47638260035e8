// SPDX-License-Identifier: MIT
// gsph-bench: runs the full step (F, Ḟ, Jaumann update — hypo-elastic, or Johnson–Cook with
// --johnson-cook —, forces, artificial viscosity and hourglass control on) on a 3-D block of n³
// particles for a fixed number of steps on each thread count of --threads (default 1 and 2, one
// after the other on the same run: the step's work does not change with the state, the lists
// being the reference configuration's), and prints particle-steps per second and per core for
// each, the speed-up over the first count, peak memory per particle and the time per phase.
//
// Usage:   gsph-bench [--cells N] [--steps S] [--threads 1,2] [--kappa K] [--no-viscosity]
//                     [--no-hourglass] [--johnson-cook] [--contact | --ogrid] [--lanes W]
// --contact: the cube as two bodies (a slab of its first 20 % in z driven at 50 m/s into the
// rest), so the step also runs the contact search and the penalty forces between them.
// --ogrid: instead of the cube, the O-grid cylinder of geometries/taylor_bar.geo (a Cartesian
// core and a cylindrical annulus, coupled by the overset band; converted in-process as
// gsph-preproc converts it), R = 3.8 mm, N/4 core cells a side, N/8 annulus cells across and
// 5N layers 0.3 mm long (N = --cells), moving at 50 m/s onto a rigid wall at its end face: the
// Taylor sample's workload, curved spaces, the band and a wall included.
// Sample:  gsph-bench --cells 46 --steps 100      (≈ 1e5 particles)
//          gsph-bench --cells 100 --steps 20      (1e6 particles)
// scripts/bench runs a set of these (and the Taylor sample through gsph-solve) against the
// build of another commit, interleaved.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "conversion.hpp"
#include "core/lanes.hpp"
#include "gmsh_input.hpp"
#include "reference/reference_builder.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/contact_fixtures.hpp"
#include "support/johnson_cook_materials.hpp"

namespace {

// Resident set of this process [bytes]: its peak (VmHWM) or now (VmRSS).
long residentBytes(const std::string& which) {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == which) {
            long kb = 0;
            status >> kb;
            return kb * 1024;
        }
        status.ignore(1 << 16, '\n');
    }
    return 0;
}

// The --ogrid layout (see above), read as gsph-solve reads a particle file.
gsph::Reference ogridReference(int cells, double kappa, std::string& layout) {
    using namespace gsph;
    const int n = std::max(2, cells / 4), nr = std::max(2, cells / 8), nz = 5 * cells;
    const double length = 0.3e-3 * nz;
    std::vector<std::string> warnings;
    const preproc::HexMesh mesh = preproc::readHexMesh(
        std::string(GSPH_SOURCE_DIR) + "/geometries/taylor_bar.geo",
        preproc::MeshReadOptions{
            {{"n", n}, {"nr", nr}, {"nz", nz}, {"L", length}, {"grading", 1.0}}},
        warnings);
    const preproc::Conversion c = preproc::convertHexMesh(mesh, {});
    char text[200];
    std::snprintf(text, sizeof text,
                  "O-grid cylinder R = 3.8 mm, L = %.1f mm: %d×%d core + %d×%d annulus, %d layers",
                  length * 1e3, n, n, 4 * n, nr, nz);
    layout = text;
    return buildReference(c.particles, std::vector<double>{7800.0}, kappa);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"gsph-bench: throughput and memory of the elastic step"};
    int cells = 46;
    int steps = 100;
    double kappa = 1.2;
    bool noViscosity = false, noHourglass = false;
    app.add_option("--cells", cells, "particles per edge of the cube (n³ particles)")
        ->check(CLI::Range(8, 400));
    app.add_option("--steps", steps, "time steps to run on each thread count")
        ->check(CLI::Range(1, 1000000));
    std::vector<int> threadCounts = {1, 2};
    app.add_option("--threads", threadCounts,
                   "thread counts to run the steps on, one after the other (speed-up against the "
                   "first)")
        ->delimiter(',')
        ->check(CLI::Range(1, 1024));
    app.add_option("--kappa", kappa, "h = κΔθ (1.2: 56 neighbours)")->check(CLI::Range(0.6, 3.0));
    app.add_flag("--no-viscosity", noViscosity, "switch artificial viscosity off");
    app.add_flag("--no-hourglass", noHourglass, "switch hourglass control off");
    bool plastic = false;
    app.add_flag("--johnson-cook", plastic,
                 "Johnson–Cook steel with damage (Weldox 460E constants) instead of elastic steel");
    bool contact = false;
    auto* contactFlag = app.add_flag(
        "--contact", contact, "two bodies in contact (slab driven into the rest of the cube)");
    bool ogrid = false;
    app.add_flag("--ogrid", ogrid,
                 "the O-grid cylinder of taylor_bar.geo (core + annulus + overset band) moving "
                 "onto a rigid wall, instead of the cube")
        ->excludes(contactFlag);
    int lanes = 8;
    app.add_option("--lanes", lanes,
                   "widest strip of the stencil kernels: 2 (SSE2), 4 (AVX2), 8 (AVX-512F; default: "
                   "the widest the processor has)")
        ->check(CLI::IsMember({2, 4, 8}));
    CLI11_PARSE(app, argc, argv);

    using namespace gsph;
    limitLanes(lanes);
    const long baseline = residentBytes("VmHWM:");
    const auto tSetup = std::chrono::steady_clock::now();
    SolverOptions options;
    if (!noViscosity) options.viscosity = {1.0, 1.0};
    if (!noHourglass) options.hourglass = 0.1;
    const double L = 0.1;  // a 10 cm steel cube
    const int slab = cells / 5;
    std::string layout;
    char cube[80];
    std::snprintf(cube, sizeof cube, "%d³ cube", cells);
    layout = cube;
    Reference ref =
        ogrid ? ogridReference(cells, kappa, layout)
        : contact
            ? testing::boxBodies(
                  {testing::Box{Vec3::Zero(), Vec3(L, L, slab * L / cells), {cells, cells, slab}},
                   testing::Box{Vec3(0, 0, slab * L / cells),
                                Vec3(L, L, (cells - slab) * L / cells),
                                {cells, cells, cells - slab}}},
                  kappa)
            : latticeReference(gradedBoxMap(Vec3(L, L, L), {}), 3, {cells, cells, cells}, 7800.0,
                               kappa);
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    Material material = HypoElastic(steel);
    if (plastic) {
        // materials/weldox_460e.toml; the 50 m/s impact below drives it well past yield.
        material = testing::withLinearEos(steel, testing::weldoxParams(), testing::weldoxDamage());
    }
    std::vector<Material> materials = {material};
    if (contact) materials.push_back(material);
    Simulation sim(std::move(ref), materials, options);
    if (ogrid) {
        // The whole bar onto a wall at its end face z = 0 (Taylor test).
        sim.addWall({"wall", Vec3::Zero(), Vec3::UnitZ()});
        sim.setVelocity([&](const Vec3&) { return Vec3(0.0, 0.0, -50.0); });
    } else {
        // A compression wave from an impact on one face: every term of the step is active.
        const double v = contact ? 50.0 : -50.0;
        sim.setVelocity([&](const Vec3& X) { return Vec3(0.0, 0.0, X[2] < 0.2 * L ? v : 0.0); });
    }
    sim.start();
    const double setupSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - tSetup).count();

    // The same steps on each thread count, timed apart (wall and process CPU time: the latter
    // less sensitive to other load on the machine).
    struct Measured {
        int threads;
        double seconds, cpuSeconds;
        PhaseTimes phases;
    };
    std::vector<Measured> measured;
    for (const int threads : threadCounts) {
        omp_set_num_threads(threads);
        const PhaseTimes before = sim.integrator().phaseTimes();
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        for (int s = 0; s < steps; ++s) sim.step();
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpuSeconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
        const PhaseTimes& after = sim.integrator().phaseTimes();
        measured.push_back({threads,
                            seconds,
                            cpuSeconds,
                            {after.kinematicsAndStress - before.kinematicsAndStress,
                             after.forces - before.forces, after.contact - before.contact,
                             after.other - before.other, after.exchange - before.exchange}});
    }

    const double n = sim.reference().size();
    const double pairs = sim.reference().pairs.pairs();
    std::size_t band = 0;
    for (Index a = 0; a < sim.reference().size(); ++a) band += sim.reference().inOversetBand(a);
    std::printf("particles            %.0f (%s), %.1f neighbours per particle, κ = %.2f\n", n,
                layout.c_str(), pairs / n, kappa);
    std::printf("overset band         %zu particles (%.1f %%)\n", band, 100.0 * band / n);
    std::size_t stencilParticles = 0, crossSpace = 0;
    for (const StencilBlocks& body : sim.integrator().stressUpdate().blocks())
        for (const ParticleBlock& block : body.blocks)
            if (block.stencil != kNoStencil)
                stencilParticles += static_cast<std::size_t>(block.size());
    const Reference& reference = sim.reference();
    for (Index a = 0; a < reference.size(); ++a) {
        bool across = !reference.crossOffset.empty() &&
                      reference.crossOffset[static_cast<std::size_t>(a) + 1] >
                          reference.crossOffset[static_cast<std::size_t>(a)];
        for (Index k = reference.pairs.begin(a); k < reference.pairs.end(a) && !across; ++k)
            across = reference.space[static_cast<std::size_t>(
                         reference.pairs.neighbor[static_cast<std::size_t>(k)])] !=
                     reference.space[static_cast<std::size_t>(a)];
        crossSpace += across;
    }
    std::printf(
        "stencil blocks       %zu particles (%.1f %%); %zu with pairs across spaces (%.1f %%)\n",
        stencilParticles, 100.0 * stencilParticles / n, crossSpace, 100.0 * crossSpace / n);
    std::printf("material             %s\n",
                plastic ? "Johnson–Cook + damage (Weldox 460E)" : "hypo-elastic steel");
    std::printf("stencil strips       up to %d lanes\n", laneWidth());
    std::printf("viscosity/hourglass  %s/%s\n", noViscosity ? "off" : "on",
                noHourglass ? "off" : "on");
    const auto* pairContact = sim.integrator().stage<PairContactStage>();
    std::printf("contact              %s (%ld pairs in contact at the end)\n",
                contact ? "two bodies"
                : ogrid ? "a rigid wall"
                        : "off",
                pairContact ? pairContact->contact().pairsInContact() : 0L);
    std::printf("setup                %.2f s (pairs, metric, first forces)\n", setupSeconds);
    // "threads N  R particle-steps/s (…)" is what scripts/bench reads.
    for (const Measured& m : measured)
        std::printf(
            "threads %-4d %.3e particle-steps/s (%.3e per core), %.3e per CPU second; %d "
            "steps in %.3f s\n",
            m.threads, n * steps / m.seconds, n * steps / m.seconds / m.threads,
            n * steps / m.cpuSeconds, steps, m.seconds);
    for (std::size_t i = 1; i < measured.size(); ++i)
        std::printf("speed-up             %.2f on %d threads against %d\n",
                    measured[0].seconds / measured[i].seconds, measured[i].threads,
                    measured[0].threads);
    std::printf("peak bytes/particle  %.0f  (process peak RSS growth / particles)\n",
                (residentBytes("VmHWM:") - baseline) / n);
    std::printf("resident bytes/particle %.0f  (after the steps: RSS growth / particles)\n",
                (residentBytes("VmRSS:") - baseline) / n);
    std::printf("pair-list bytes/particle %.0f\n", sim.reference().pairs.bytes() / n);
    // The staged CSR pairs' size, and how full the CSR path's SIMD lanes are: masked strips'
    // entry-lanes holding a pair, runs' entries that are not padding.
    double staged = 0.0, stripLanes = 0.0, stripPairs = 0.0, runEntries = 0.0, runPairs = 0.0;
    for (const CsrPairWeights& body : sim.integrator().stressUpdate().staged()) {
        staged += static_cast<double>(body.bytes());
        for (const MaskedStrip& strip : body.strips) {
            const auto entries = static_cast<std::size_t>(strip.deltaEnd - strip.deltaBegin);
            for (std::size_t j = 0; j < entries * kPairLanes; ++j)
                stripPairs += body.stripPairs.valid[strip.base + j] != 0.0 ? 1.0 : 0.0;
            stripLanes += static_cast<double>(entries * kPairLanes);
        }
        for (std::size_t a = 0; a + 1 < body.begin.size(); ++a)
            for (std::size_t j = body.begin[a]; j < body.begin[a + 1]; ++j) {
                runEntries += 1.0;
                runPairs += body.pairs.share[j] != 0.0 ? 1.0 : 0.0;
            }
    }
    std::printf("staged CSR pairs bytes/particle %.0f (neighbors/staged_pairs.hpp)\n", staged / n);
    if (stripLanes + runEntries > 0.0)
        std::printf(
            "CSR lanes            masked strips %.0f pairs in %.0f lanes (%.0f %%), runs %.0f "
            "in %.0f (%.0f %%)\n",
            stripPairs, stripLanes, 100.0 * stripPairs / std::max(stripLanes, 1.0), runPairs,
            runEntries, 100.0 * runPairs / std::max(runEntries, 1.0));
    for (const Measured& m : measured)
        std::printf(
            "phases, %d thread%s kinematics+stress %.1f %%, forces %.1f %%, contact %.1f %%, "
            "other %.1f %%\n",
            m.threads, m.threads == 1 ? " " : "s", 100 * m.phases.kinematicsAndStress / m.seconds,
            100 * m.phases.forces / m.seconds, 100 * m.phases.contact / m.seconds,
            100 * m.phases.other / m.seconds);
    return 0;
}
