// SPDX-License-Identifier: MIT
#include "summary.hpp"

#include <cstdio>
#include <vector>

#include "core/version.hpp"

namespace gsph::preproc {

namespace {

std::string format(const char* fmt, auto... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, fmt, args...);
    return buffer;
}

std::string join(const std::vector<int>& values) {
    std::string s;
    for (int v : values) {
        if (!s.empty()) s += ',';
        s += std::to_string(v);
    }
    return s;
}

}  // namespace

void printSpaces(std::ostream& out, const std::string& input, const std::string& parameters,
                 const std::string& output, const ParticleFile& pf, const ConversionStats& stats) {
    const auto spaces = pf.spaces.size();
    std::vector<long> perSpace(spaces, 0);
    std::vector<Index> bodyOfSpace(spaces, 0);
    for (Index a = 0; a < pf.size(); ++a) {
        ++perSpace[pf.space[a]];
        bodyOfSpace[pf.space[a]] = pf.body[a];
    }
    out << "gsph-preproc " << kVersion << ": " << input
        << (parameters.empty() ? "" : " (" + parameters + ")") << " -> " << output << "\n";
    const bool plane = pf.dimension == 2;
    out << format("  particles  %ld in %zu space%s, %zu bod%s, from %zu %s\n",
                  static_cast<long>(pf.size()), spaces, spaces == 1 ? "" : "s", pf.bodies.size(),
                  pf.bodies.size() == 1 ? "y" : "ies", stats.hexes,
                  plane ? "quadrangles (2-D)" : "hexahedra");
    for (std::size_t s = 0; s < spaces; ++s) {
        const LatticeSpace& sp = pf.spaces[s];
        std::string periodic;
        for (int d = 0; d < 3; ++d) {
            if (sp.periodic[d]) periodic += "ijk"[d];
        }
        const std::string cells = format("%dx%dx%d", sp.cells[0], sp.cells[1], sp.cells[2]);
        out << format(
            "  space %-3zu body %-3d cells %-16s periodic %-4s particles %-9ld gmsh %s %s\n", s,
            bodyOfSpace[s], cells.c_str(), periodic.empty() ? "-" : periodic.c_str(), perSpace[s],
            plane ? "surfaces" : "volumes", join(stats.spaceVolumes[s]).c_str());
    }
    out.flush();
}

void printSummary(std::ostream& out, const ParticleFile& pf, const ConversionStats& stats,
                  const Timings& t) {
    std::vector<long> perBody(pf.bodies.size(), 0);
    std::vector<double> bodyVolume(pf.bodies.size(), 0.0);
    for (Index a = 0; a < pf.size(); ++a) {
        ++perBody[pf.body[a]];
        bodyVolume[pf.body[a]] += pf.volume[a];
    }
    for (std::size_t b = 0; b < pf.bodies.size(); ++b) {
        const BodyInfo& body = pf.bodies[b];
        const std::string name = body.name.empty()
                                     ? (body.sourceTag < 0 ? "(whole mesh)" : "(unnamed)")
                                     : "'" + body.name + "'";
        // A 2-D file's volumes are areas (per metre of depth).
        out << format("  body %-3zu %-20s particles %-9ld %s %.6e %s\n", b, name.c_str(),
                      perBody[b], pf.dimension == 2 ? "area" : "volume", bodyVolume[b],
                      pf.dimension == 2 ? "m^2" : "m^3");
    }
    out << format("  spacing    %s edge length from %.4e m to %.4e m\n",
                  pf.dimension == 2 ? "quad" : "hex", stats.minEdge, stats.maxEdge);
    for (std::size_t b = 0; b < stats.lattice.size(); ++b) {
        const ConversionStats::Lattice& l = stats.lattice[b];
        if (pf.dimension == 2) {
            out << format(
                "  lattice    body %-3zu uniform Cartesian, spacing %.4e x %.4e m, box %dx%d "
                "cells; area %.6e m^2 = %.4f of the mesh's\n",
                b, l.spacing[0], l.spacing[1], l.cells[0], l.cells[1], bodyVolume[b],
                bodyVolume[b] / l.meshVolume);
            continue;
        }
        out << format(
            "  lattice    body %-3zu uniform Cartesian, spacing %.4e x %.4e x %.4e m, box %dx%dx%d "
            "cells; volume %.6e m^3 = %.4f of the mesh's\n",
            b, l.spacing[0], l.spacing[1], l.spacing[2], l.cells[0], l.cells[1], l.cells[2],
            bodyVolume[b], bodyVolume[b] / l.meshVolume);
    }
    if (pf.sets.empty()) {
        out << "  sets       none\n";
    } else {
        std::string sets;
        for (const auto& [name, members] : pf.sets) {
            if (!sets.empty()) sets += ", ";
            sets += format("'%s' %zu", name.c_str(), members.size());
        }
        out << "  sets       " << sets << "\n";
    }
    for (std::size_t s = 0; s < stats.metric.size(); ++s) {
        const MetricReport& m = stats.metric[s];
        if (pf.dimension == 2) {  // the slab's unit depth says nothing of the 2-D metric
            out << format(
                "  metric     space %-3zu worst cond(dX/dtheta) in the plane %.3f, det at cell "
                "corners >= %.3f of centre\n",
                s, m.inPlaneCondition, m.cornerRatio);
            continue;
        }
        const std::string plane = m.oneLayerAxis < 0
                                      ? ""
                                      : format(" (in-plane %.3f: one cell along %c)",
                                               m.inPlaneCondition, "ijk"[m.oneLayerAxis]);
        out << format(
            "  metric     space %-3zu worst cond(dX/dtheta) %.3f%s, det at cell corners >= %.3f of "
            "centre\n",
            s, m.condition, plane.c_str(), m.cornerRatio);
    }
    if (!stats.transients.empty()) {
        out << format(
            "  overset    kappa %.3g: a particle within 2 kappa dtheta = %.3g dtheta of another "
            "space's particles is transient there\n",
            stats.oversetKappa, 2.0 * stats.oversetKappa);
    }
    long cut = 0;
    for (const HoleCutReport& c : stats.cuts) cut += c.particles;
    if (cut > 0) {
        out << format("  kept       %ld particles after hole cutting (%ld cut)\n",
                      static_cast<long>(pf.size()), cut);
    }
    for (const HoleCutReport& c : stats.cuts) {
        if (c.particles == 0 && c.doubleCounted == 0.0) {
            out << format("  cut        space %d by space %d: none (they do not overlap)\n",
                          c.space, c.by);
            continue;
        }
        out << format(
            "  cut        space %d by space %d: %ld particles (%.6e m^3); gap %.3e m^3, "
            "double-counted %.3e m^3\n",
            c.space, c.by, c.particles, c.volume, c.gap, c.doubleCounted);
    }
    for (const TransientReport& tr : stats.transients) {
        if (tr.continued) {
            out << format(
                "  transient  space %d in space %d: %ld particles, space %d's lattice continued "
                "across the block faces they share, up to %.3f dtheta past it\n",
                tr.space, tr.in, tr.particles, tr.in, tr.maxExtrapolation);
            continue;
        }
        out << format(
            "  transient  space %d in space %d: %ld particles, extrapolated up to %.3f dtheta past "
            "space %d's lattice%s\n",
            tr.space, tr.in, tr.particles, tr.maxExtrapolation, tr.in,
            tr.ambiguous == 0
                ? ""
                : format(" (%ld reached by two extensions: the nearer kept)", tr.ambiguous)
                      .c_str());
    }
    out << format("  gluing     %d of %d shared block faces lie inside a space%s\n",
                  stats.honouredFaces, stats.sharedFaces,
                  stats.exhaustiveGluing ? "" : " (search stopped early)");
    out << format("  time       read+mesh %.3f s, convert %.3f s, write %.3f s, total %.3f s\n",
                  t.read, t.convert, t.write, t.total);
}

}  // namespace gsph::preproc
