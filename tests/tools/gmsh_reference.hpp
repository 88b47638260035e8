// SPDX-License-Identifier: MIT
// The hexahedra of a mesh as gmsh itself reports them, for checking gsph-preproc against an
// independent source: element tags, node tags, barycentres (gmsh's getBarycenters) and exact
// volumes (gmsh's Jacobians at 2×2×2 Gauss points, toolchain.md).
#pragma once

#include <gmsh.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace gsph::test {

struct GmshHexes {
    std::vector<std::size_t> tags;
    std::vector<std::array<std::size_t, 8>> nodes;
    std::vector<Vec3> barycentre;
    std::vector<double> volume;
    std::map<std::size_t, std::size_t> indexOfTag;
};

/// Opens `path` (meshing a .geo in 3-D) with the given -setnumber parameters; optionally
/// writes the mesh to `writeMsh`.
/// (Parameters go through a wrapper .geo, not gmsh's -setnumber, which gmsh 4.8 keeps for the
/// rest of the process; ONELAB parameters are cleared for the same reason.)
inline GmshHexes gmshHexes(const std::string& path,
                           const std::vector<std::pair<std::string, double>>& parameters = {},
                           const std::string& writeMsh = "") {
    std::string open = path;
    const std::string wrapper = std::filesystem::temp_directory_path() /
                                ("gsph-test-wrapper-" + std::to_string(::getpid()) + ".geo");
    if (!parameters.empty()) {
        std::ofstream out(wrapper);
        for (const auto& [name, value] : parameters) {
            char text[64];
            std::snprintf(text, sizeof text, "%.17g", value);
            out << name << " = " << text << ";\n";
        }
        out << "Include \"" << path << "\";\n";
        open = wrapper;
    }
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::onelab::clear();
    gmsh::open(open);
    std::filesystem::remove(wrapper);
    if (path.size() > 4 && path.substr(path.size() - 4) == ".geo") gmsh::model::mesh::generate(3);
    if (!writeMsh.empty()) gmsh::write(writeMsh);

    GmshHexes g;
    std::vector<std::size_t> nodeTags;
    gmsh::model::mesh::getElementsByType(5, g.tags, nodeTags);
    std::vector<double> bary;
    gmsh::model::mesh::getBarycenters(5, -1, false, true, bary);
    std::vector<double> local, weights, jac, det, coord;
    gmsh::model::mesh::getIntegrationPoints(5, "Gauss2", local, weights);
    gmsh::model::mesh::getJacobians(5, local, jac, det, coord);
    const std::size_t q = weights.size();
    for (std::size_t e = 0; e < g.tags.size(); ++e) {
        std::array<std::size_t, 8> n{};
        for (int k = 0; k < 8; ++k) n[k] = nodeTags[8 * e + k];
        g.nodes.push_back(n);
        g.barycentre.emplace_back(bary[3 * e], bary[3 * e + 1], bary[3 * e + 2]);
        double v = 0.0;
        for (std::size_t p = 0; p < q; ++p) v += det[q * e + p] * weights[p];
        g.volume.push_back(v);
        g.indexOfTag[g.tags[e]] = e;
    }
    gmsh::finalize();
    return g;
}

}  // namespace gsph::test
