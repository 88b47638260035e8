// SPDX-License-Identifier: MIT
#include "mesh_process.hpp"

#include <cstdint>

#include "core/error.hpp"
#include "io/child_process.hpp"

namespace gsph::preproc {
namespace {

void writeMesh(ByteWriter& w, const HexMesh& m, const std::vector<std::string>& warnings) {
    w.text(m.source);
    w.value(m.dimension);
    w.array(m.nodes);
    w.array(m.hexes);
    w.array(m.hexTags);
    w.array(m.volumes);
    w.value<std::uint64_t>(m.volumeGroups.size());
    for (const VolumeGroup& g : m.volumeGroups) {
        w.value(g.tag);
        w.text(g.name);
        w.array(g.volumes);
    }
    w.value<std::uint64_t>(m.surfaceGroups.size());
    for (const SurfaceGroup& g : m.surfaceGroups) {
        w.value(g.tag);
        w.text(g.name);
        w.array(g.quads);
    }
    w.value<std::uint64_t>(warnings.size());
    for (const std::string& s : warnings) w.text(s);
}

HexMesh readMesh(ByteReader& r, std::vector<std::string>& warnings) {
    HexMesh m;
    m.source = r.text();
    m.dimension = r.value<int>();
    m.nodes = r.array<Vec3>();
    m.hexes = r.array<std::array<Index, 8>>();
    m.hexTags = r.array<std::size_t>();
    m.volumes = r.array<HexVolume>();
    m.volumeGroups.resize(r.value<std::uint64_t>());
    for (VolumeGroup& g : m.volumeGroups) {
        g.tag = r.value<int>();
        g.name = r.text();
        g.volumes = r.array<int>();
    }
    m.surfaceGroups.resize(r.value<std::uint64_t>());
    for (SurfaceGroup& g : m.surfaceGroups) {
        g.tag = r.value<int>();
        g.name = r.text();
        g.quads = r.array<std::array<Index, 4>>();
    }
    const auto n = r.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) warnings.push_back(r.text());
    return m;
}

}  // namespace

HexMesh readHexMeshInChild(const std::filesystem::path& input, const MeshReadOptions& options,
                           std::vector<std::string>& warnings) {
    const std::string source = input.string();
    const std::string bytes = runInChild(
        source, "gmsh",
        [&](ByteWriter& w) {
            std::vector<std::string> found;
            const HexMesh mesh = readHexMesh(input, options, found);
            writeMesh(w, mesh, found);
        },
        [&](const std::string& reason) {
            throw MeshError(source + ": gmsh crashed while reading or meshing it (" + reason +
                            "); check the file and its parameters (a zero or negative grading "
                            "or cell count is a common cause)");
        });
    ByteReader r(bytes, source);
    return readMesh(r, warnings);
}

}  // namespace gsph::preproc
