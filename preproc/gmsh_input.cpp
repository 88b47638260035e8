// SPDX-License-Identifier: MIT
#include "gmsh_input.hpp"

#include <gmsh.h>
#include <omp.h>
#include <Eigen/Geometry>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/error.hpp"

namespace gsph::preproc {

namespace {

constexpr const char* kParameterEcho = "gsph-parameter ";
constexpr int kHex8 = 5;   // gmsh element type: 8-node hexahedron
constexpr int kQuad4 = 3;  // gmsh element type: 4-node quadrangle
constexpr int kLine2 = 1;  // gmsh element type: 2-node line

/// One gmsh session: initialise, finalise on scope exit and restore OpenMP's thread count
/// (toolchain.md: gmsh::initialize sets it to 1). ONELAB parameters survive gmsh::finalize in
/// gmsh 4.8 and would leak DefineConstant values from one .geo into the next: they are cleared.
class GmshSession {
  public:
    GmshSession() : threads_(omp_get_max_threads()) {
        try {
            gmsh::initialize(0, nullptr, false);
            gmsh::option::setNumber("General.Terminal", 0);
            // Log errors instead of throwing them: gmsh 4.8 throws from inside its OpenMP
            // meshing loops, where an exception cannot be caught (std::terminate). Errors are
            // read back from the log after each call (firstError).
            gmsh::option::setNumber("General.AbortOnError", 0);
            gmsh::onelab::clear();
            gmsh::logger::start();
        } catch (...) {
            omp_set_num_threads(threads_);
            throw;
        }
    }
    ~GmshSession() {
        try {
            gmsh::logger::stop();
            gmsh::finalize();
        } catch (...) {  // nothing useful can be done while unwinding
        }
        omp_set_num_threads(threads_);
    }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

  private:
    int threads_;
};

/// A .geo opened with parameters is opened through a temporary wrapper that defines them and
/// then includes it. (gmsh's `-setnumber`, passed to gmsh::initialize, would do the same for one
/// file, but gmsh 4.8 keeps command-line numbers for the rest of the process.) DefineConstant
/// leaves an already defined name alone, so the wrapper's values override its defaults;
/// messages and relative paths inside the .geo still refer to the .geo itself.
class ParameterWrapper {
  public:
    ParameterWrapper(const std::filesystem::path& input,
                     const std::vector<std::pair<std::string, double>>& parameters)
        : path_(input) {
        if (parameters.empty()) return;
        static std::atomic<int> counter{0};
        path_ =
            std::filesystem::temp_directory_path() / ("gsph-preproc-" + std::to_string(::getpid()) +
                                                      "-" + std::to_string(counter++) + ".geo");
        std::ofstream out(path_);
        for (const auto& [name, value] : parameters) {
            const bool valid =
                !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                std::all_of(name.begin(), name.end(),
                            [](unsigned char c) { return std::isalnum(c) || c == '_'; });
            if (!valid)
                throw InputError(input.string() + ": '" + name + "' is not a parameter name");
            char text[64];
            std::snprintf(text, sizeof text, "%.17g", value);
            out << name << " = " << text << ";\n";
        }
        out << "Include \"" << std::filesystem::absolute(input).string() << "\";\n";
        // Read back after parsing: a plain assignment in the .geo would have replaced the value.
        for (const auto& [name, value] : parameters)
            out << "Printf(\"" << kParameterEcho << name << " = %.17g\", " << name << ");\n";
        out.close();
        if (!out) throw IoError(path_.string() + ": cannot write a temporary file");
        owned_ = true;
    }
    ~ParameterWrapper() {
        std::error_code ec;
        if (owned_) std::filesystem::remove(path_, ec);
    }
    ParameterWrapper(const ParameterWrapper&) = delete;
    ParameterWrapper& operator=(const ParameterWrapper&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    bool owned_ = false;
};

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
}

/// gmsh's reason for a failure: the exception text, else its last logged error.
std::string gmshReason(const std::string& thrown) {
    if (!thrown.empty()) return oneLine(thrown);
    std::string last;
    gmsh::logger::getLastError(last);
    return last.empty() ? std::string("unknown gmsh error") : oneLine(last);
}

/// The first error of a gmsh log, or "".
std::string firstError(const std::vector<std::string>& log) {
    const std::string prefix = "Error: ";
    for (const std::string& line : log) {
        if (line.rfind(prefix, 0) == 0) return oneLine(line.substr(prefix.size()));
    }
    return "";
}

void collectWarnings(const std::vector<std::string>& log, std::vector<std::string>& warnings) {
    const std::string prefix = "Warning: ";
    for (const std::string& line : log) {
        if (line.rfind(prefix, 0) == 0)
            warnings.push_back("gmsh: " + oneLine(line.substr(prefix.size())));
    }
}

/// Every --set NAME=VALUE must reach the .geo: its name must occur in the file, and the value
/// the .geo ends up with (echoed by the wrapper) must be the one given; a plain assignment
/// `NAME = …;` in the .geo (rather than a DefineConstant) replaces it and is refused here.
void checkParameters(const std::filesystem::path& input,
                     const std::vector<std::pair<std::string, double>>& parameters,
                     const std::vector<std::string>& log) {
    if (parameters.empty()) return;
    std::ifstream in(input);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto isWordChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
    };
    std::vector<std::string> names;
    gmsh::onelab::getNames(names, "Parameters/.*");
    std::string known;
    for (const std::string& n : names)
        known += (known.empty() ? "" : ", ") + n.substr(n.find('/') + 1);
    for (const auto& [name, value] : parameters) {
        bool occurs = false;
        for (std::size_t at = text.find(name); at != std::string::npos && !occurs;
             at = text.find(name, at + 1))
            occurs = (at == 0 || !isWordChar(text[at - 1])) &&
                     (at + name.size() == text.size() || !isWordChar(text[at + name.size()]));
        char given[64];
        std::snprintf(given, sizeof given, "%.17g", value);
        if (!occurs)
            throw InputError(
                input.string() + ": --set " + name + "=" + given + ": the file has no parameter '" +
                name + "'" +
                (known.empty() ? "" : " (its DefineConstant parameters: " + known + ")"));
        const std::string echo = kParameterEcho + name + " = ";
        for (const std::string& line : log) {
            const std::size_t at = line.find(echo);
            if (at == std::string::npos) continue;
            const double seen = std::strtod(line.c_str() + at + echo.size(), nullptr);
            if (seen != value) {
                char got[64];
                std::snprintf(got, sizeof got, "%.17g", seen);
                throw InputError(input.string() + ": --set " + name + "=" + given +
                                 " has no effect: the file assigns " + name + " = " + got +
                                 " itself; only parameters declared with DefineConstant[...] "
                                 "can be set from the command line");
            }
        }
    }
}

/// Peak memory of meshing and converting one hexahedron (gmsh's mesh, HexMesh, the
/// conversion), measured: 1.66e6 hexes of geometries/taylor_bar.geo (refine = 6) peak at
/// 737 MB, 444 B each; rounded up.
constexpr double kBytesPerHex = 500.0;

/// Memory the system can give without swapping [bytes] (MemAvailable), 0 if unknown.
double availableMemory() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kb = 0.0;
    std::string unit;
    while (in >> key >> kb >> unit)
        if (key == "MemAvailable:") return kb * 1024.0;
    return 0.0;
}

/// Σ log(segments) over the boundary curves of `entity`, and how many curves it has.
std::pair<double, std::size_t> logCurveSegments(const std::pair<int, int>& entity) {
    gmsh::vectorpair curves;
    gmsh::model::getBoundary({{entity.first, std::abs(entity.second)}}, curves, false, false,
                             false);
    double logSum = 0.0;
    for (const auto& [dim, tag] : curves) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, std::abs(tag));
        std::size_t segments = 0;
        for (const auto& e : elementTags) segments += e.size();
        logSum += std::log(static_cast<double>(std::max<std::size_t>(segments, 1)));
    }
    return {logSum, curves.size()};
}

/// After the curve mesh: the hexahedra each volume will hold (in 2-D: the quadrangles of each
/// surface, each one hex once extruded), from its edges' cell counts (a structured face of a×b
/// cells has edges of a, b, a, b cells: the product of the four is (ab)²; a block of i×j×k cells
/// has faces of ij, jk and ik cells, two each, whose product is (ijk)⁴), and the memory they
/// need; refuses what this machine cannot hold and warns above half of it.
void checkMeshSize(const std::string& source, int meshDimension,
                   std::vector<std::string>& warnings) {
    gmsh::vectorpair blocks;
    gmsh::model::getEntities(blocks, meshDimension);
    double hexes = 0.0;
    for (const auto& block : blocks) {
        if (meshDimension == 2) {
            const auto [logSum, curves] = logCurveSegments(block);
            if (curves == 4) hexes += std::exp(0.5 * logSum);
            continue;
        }
        gmsh::vectorpair faces;
        gmsh::model::getBoundary({block}, faces, false, false, false);
        if (faces.size() != 6) continue;  // not a six-faced block: no estimate
        double logProduct = 0.0;          // Σ over faces of log(cells of the face)
        for (const auto& face : faces) {
            const auto [logFace, curves] = logCurveSegments(face);
            logProduct += curves == 4 ? 0.5 * logFace : 0.0;
        }
        hexes += std::exp(0.25 * logProduct);
    }
    const double need = hexes * kBytesPerHex, have = availableMemory();
    if (have <= 0.0 || need <= 0.5 * have) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "the mesh will have about %.3g hexahedra, which need about %.3g GB to mesh and "
                  "convert; this machine has %.3g GB available",
                  hexes, need / 1e9, have / 1e9);
    if (need > have)
        throw InputError(source + ": " + text +
                         ": coarsen the mesh (its parameters, e.g. --set refine=...) or convert "
                         "on a machine with more memory");
    warnings.push_back(std::string(text) + " (more than half of it)");
}

/// Plural name of a gmsh element type, for messages. Common types are named here (asking gmsh
/// about a prism leaks memory inside gmsh 4.8, which sanitizer builds report).
std::string elementName(int type) {
    static const std::map<int, const char*> kNames = {
        {2, "3-node triangles"},    {3, "4-node quadrangles"},  {4, "4-node tetrahedra"},
        {5, "8-node hexahedra"},    {6, "6-node prisms"},       {7, "5-node pyramids"},
        {9, "6-node triangles"},    {10, "9-node quadrangles"}, {11, "10-node tetrahedra"},
        {12, "27-node hexahedra"},  {13, "18-node prisms"},     {14, "14-node pyramids"},
        {16, "8-node quadrangles"}, {17, "20-node hexahedra"},  {18, "15-node prisms"},
        {19, "13-node pyramids"}};
    if (const auto it = kNames.find(type); it != kNames.end()) return it->second;
    std::string name;
    int dim = 0, order = 0, nodes = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
    return "elements of type '" + name + "'";
}

/// Node tag → dense node id (ids in ascending tag order).
class NodeIds {
  public:
    NodeIds(const std::vector<std::size_t>& tags, const std::vector<double>& coords,
            std::vector<Vec3>& nodes) {
        std::vector<std::size_t> order(tags.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
        nodes.resize(tags.size());
        const std::size_t maxTag = tags.empty() ? 0 : tags[order.back()];
        dense_ = maxTag <= 2 * tags.size() + 1024;
        if (dense_) denseIds_.assign(maxTag + 1, -1);
        for (std::size_t id = 0; id < order.size(); ++id) {
            const std::size_t p = order[id];
            nodes[id] = Vec3(coords[3 * p], coords[3 * p + 1], coords[3 * p + 2]);
            if (dense_) {
                denseIds_[tags[p]] = static_cast<Index>(id);
            } else {
                sparseIds_[tags[p]] = static_cast<Index>(id);
            }
        }
    }
    /// -1 if the tag is unknown.
    Index operator()(std::size_t tag) const {
        if (dense_) return tag < denseIds_.size() ? denseIds_[tag] : -1;
        const auto it = sparseIds_.find(tag);
        return it == sparseIds_.end() ? -1 : it->second;
    }

  private:
    bool dense_ = true;
    std::vector<Index> denseIds_;
    std::unordered_map<std::size_t, Index> sparseIds_;
};

template <std::size_t N>
void appendElements(const std::string& source, const std::vector<std::size_t>& nodeTags,
                    const NodeIds& ids, std::vector<std::array<Index, N>>& out) {
    for (std::size_t e = 0; e + N <= nodeTags.size(); e += N) {
        std::array<Index, N> element{};
        for (std::size_t k = 0; k < N; ++k) {
            element[k] = ids(nodeTags[e + k]);
            if (element[k] < 0) {
                throw MeshError(source + ": an element refers to node " +
                                std::to_string(nodeTags[e + k]) + ", which does not exist");
            }
        }
        out.push_back(element);
    }
}

/// gmsh turns the hexahedra of a structured block that collapse onto a line into prisms (a
/// rectangle revolved about an axis it touches, a 3-corner transfinite surface extruded). When
/// prisms come with hexahedra and the nodes only prisms have lie on one line, that line is the
/// axis of a cylindrical space: this says so; otherwise it returns "".
std::string collapsedAxisNote(const std::vector<int>& types,
                              const std::vector<std::vector<std::size_t>>& nodeTags,
                              const NodeIds& ids, const std::vector<Vec3>& nodes) {
    constexpr int kPrism6 = 6;
    std::vector<Index> hexNodes, prismNodes;
    for (std::size_t t = 0; t < types.size(); ++t) {
        std::vector<Index>& to = types[t] == kHex8 ? hexNodes : prismNodes;
        if (types[t] != kHex8 && types[t] != kPrism6) continue;
        for (std::size_t tag : nodeTags[t]) to.push_back(ids(tag));
    }
    std::sort(hexNodes.begin(), hexNodes.end());
    std::sort(prismNodes.begin(), prismNodes.end());
    prismNodes.erase(std::unique(prismNodes.begin(), prismNodes.end()), prismNodes.end());
    std::vector<Vec3> axis;
    for (Index n : prismNodes) {
        if (n >= 0 && !std::binary_search(hexNodes.begin(), hexNodes.end(), n)) {
            axis.push_back(nodes[static_cast<std::size_t>(n)]);
        }
    }
    if (hexNodes.empty() || axis.empty()) return "";
    auto farthest = [&](const Vec3& from) {
        return *std::max_element(axis.begin(), axis.end(), [&](const Vec3& a, const Vec3& b) {
            return (a - from).squaredNorm() < (b - from).squaredNorm();
        });
    };
    const Vec3 a = farthest(axis.front()), b = farthest(a);
    const double length = (b - a).norm();
    for (const Vec3& x : axis) {
        if (length > 0.0 && ((x - a).cross(b - a)).norm() > 1e-9 * length * length) return "";
    }
    char where[160];
    std::snprintf(where, sizeof where, "(%.6g, %.6g, %.6g) to (%.6g, %.6g, %.6g)", a[0], a[1], a[2],
                  b[0], b[1], b[2]);
    return std::string(": the block collapses onto the line from ") + where +
           ", like a single cylindrical space on its axis, where dX/dtheta is singular; cover the "
           "axis with a Cartesian core block (an O-grid, as in geometries/taylor_bar.geo)";
}

/// How many elements of type `wanted` an entity holds, and the others as "N name, …" ("" if
/// none).
std::pair<std::size_t, std::string> elementCensus(
    const std::vector<int>& types, const std::vector<std::vector<std::size_t>>& elementTags,
    int wanted) {
    std::size_t count = 0;
    std::string others;
    for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] == wanted) {
            count = elementTags[t].size();
            continue;
        }
        if (!others.empty()) others += ", ";
        others += std::to_string(elementTags[t].size()) + " " + elementName(types[t]);
    }
    return {count, others};
}

void readVolumes(const std::string& source, const NodeIds& ids, HexMesh& mesh) {
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, 3);
    std::sort(entities.begin(), entities.end());
    for (const auto& [dim, tag] : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, tag);
        const auto [hexes, others] = elementCensus(types, elementTags, kHex8);
        if (!others.empty()) {
            const std::string axis = collapsedAxisNote(types, nodeTags, ids, mesh.nodes);
            throw MeshError(
                source + ": volume " + std::to_string(tag) + " holds " + others +
                (hexes > 0 ? " besides " + std::to_string(hexes) + " 8-node hexahedra" : "") +
                (axis.empty() ? "; gsph-preproc needs structured blocks of 8-node hexahedra "
                                "(Transfinite Volume + Recombine)"
                              : axis));
        }
        if (hexes == 0) continue;
        HexVolume volume{tag, static_cast<Index>(mesh.hexes.size()), static_cast<Index>(hexes)};
        const std::size_t at = std::find(types.begin(), types.end(), kHex8) - types.begin();
        appendElements<8>(source, nodeTags[at], ids, mesh.hexes);
        mesh.hexTags.insert(mesh.hexTags.end(), elementTags[at].begin(), elementTags[at].end());
        mesh.volumes.push_back(volume);
    }
}

/// The quadrangles of a physical surface group (3-D: the faces of its surfaces' quads).
void appendGroupQuads(const std::string& source, const NodeIds& ids, const std::string& label,
                      int surface, SurfaceGroup& group) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elementTags, nodeTags;
    gmsh::model::mesh::getElements(types, elementTags, nodeTags, 2, surface);
    for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] != kQuad4) {
            throw MeshError(source + ": physical surface " + label + " (surface " +
                            std::to_string(surface) + ") holds " + elementName(types[t]) +
                            "; particle sets need 4-node quadrangles (Recombine Surface)");
        }
        appendElements<4>(source, nodeTags[t], ids, group.quads);
    }
}

/// The extruded segments of a physical curve group in a 2-D mesh: each 2-node line (a, b)
/// becomes the side quad (a, b, b', a') of the slab, a' the copy of a at z = 1.
void appendGroupSegments(const std::string& source, const NodeIds& ids, const std::string& label,
                         int curve, Index planeNodes, SurfaceGroup& group) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elementTags, nodeTags;
    gmsh::model::mesh::getElements(types, elementTags, nodeTags, 1, curve);
    for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] != kLine2) {
            throw MeshError(source + ": physical curve " + label + " (curve " +
                            std::to_string(curve) + ") holds " + elementName(types[t]) +
                            "; particle sets of a 2-D mesh need 2-node lines");
        }
        std::vector<std::array<Index, 2>> segments;
        appendElements<2>(source, nodeTags[t], ids, segments);
        for (const auto& [a, b] : segments)
            group.quads.push_back({a, b, b + planeNodes, a + planeNodes});
    }
}

/// Physical groups: in 3-D volume groups are bodies and surface groups sets; in 2-D surface
/// groups are bodies and curve groups sets.
void readGroups(const std::string& source, const NodeIds& ids, HexMesh& mesh,
                std::vector<std::string>& warnings) {
    const bool plane = mesh.dimension == 2;
    const auto planeNodes = static_cast<Index>(mesh.nodes.size() / 2);
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    std::sort(groups.begin(), groups.end());
    for (const auto& [dim, tag] : groups) {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
        const std::string label =
            name.empty() ? "(tag " + std::to_string(tag) + ")" : "'" + name + "'";
        if (dim == mesh.dimension) {
            mesh.volumeGroups.push_back({tag, name, entities});
        } else if (dim == mesh.dimension - 1) {
            SurfaceGroup group{tag, name, {}};
            for (int entity : entities) {
                if (plane) {
                    appendGroupSegments(source, ids, label, entity, planeNodes, group);
                } else {
                    appendGroupQuads(source, ids, label, entity, group);
                }
            }
            mesh.surfaceGroups.push_back(std::move(group));
        } else {
            static const char* const kKinds[] = {"point ", "curve ", "surface ", "volume "};
            warnings.push_back(
                "physical " + std::string(kKinds[std::clamp(dim, 0, 3)]) + label + " is ignored (" +
                (plane ? "in a 2-D mesh surface groups are bodies, curve groups are sets"
                       : "volume groups are bodies, surface groups are sets") +
                ")");
        }
    }
}

/// The number of 2-D elements of the model, and the first surface with an element that has a
/// node no hexahedron uses (-1 if none, or if there are no hexahedra): such a surface is not
/// part of the 3-D mesh's boundary but a 2-D mesh beside it.
std::pair<std::size_t, long> countPlaneElements(const NodeIds& ids, const HexMesh& mesh) {
    std::vector<char> hexNode(mesh.nodes.size(), 0);
    for (const auto& hex : mesh.hexes)
        for (Index n : hex) hexNode[static_cast<std::size_t>(n)] = 1;
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::size_t count = 0;
    long stray = -1;
    for (const auto& [dim, tag] : surfaces) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, tag);
        for (std::size_t t = 0; t < types.size(); ++t) {
            count += elementTags[t].size();
            if (stray >= 0 || mesh.hexes.empty()) continue;
            for (std::size_t tagOfNode : nodeTags[t]) {
                const Index n = ids(tagOfNode);
                if (n >= 0 && !hexNode[static_cast<std::size_t>(n)]) {
                    stray = tag;
                    break;
                }
            }
        }
    }
    return {count, stray};
}

/// A 2-D mesh: every surface must hold 4-node quadrangles only, in the plane z = 0; each
/// quad becomes a hex of unit depth (nodes n and n + N at z = 0 and z = 1, N the plane's
/// nodes), turned counter-clockwise first so that the hex's Jacobian is positive.
void readSurfacesAsSlab(const std::string& source, const NodeIds& ids, HexMesh& mesh) {
    double extent = 0.0;
    for (const Vec3& x : mesh.nodes) extent = std::max(extent, x.cwiseAbs().maxCoeff());
    for (const Vec3& x : mesh.nodes) {
        if (std::abs(x[2]) > 1e-9 * extent) {
            char where[128];
            std::snprintf(where, sizeof where, "(%.6g, %.6g, %.6g)", x[0], x[1], x[2]);
            throw MeshError(source + ": a 2-D mesh must lie in the plane z = 0 (its node at " +
                            where + " does not)");
        }
    }
    const auto planeNodes = static_cast<Index>(mesh.nodes.size());
    mesh.nodes.resize(2 * mesh.nodes.size());
    for (Index n = 0; n < planeNodes; ++n) {
        mesh.nodes[n][2] = 0.0;
        mesh.nodes[n + planeNodes] = Vec3(mesh.nodes[n][0], mesh.nodes[n][1], 1.0);
    }
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::sort(surfaces.begin(), surfaces.end());
    for (const auto& [dim, tag] : surfaces) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, tag);
        const auto [quads, others] = elementCensus(types, elementTags, kQuad4);
        if (!others.empty()) {
            throw MeshError(
                source + ": surface " + std::to_string(tag) + " holds " + others +
                (quads > 0 ? " besides " + std::to_string(quads) + " 4-node quadrangles" : "") +
                "; gsph-preproc needs structured blocks of 4-node quadrangles in 2-D "
                "(Transfinite Surface + Recombine Surface)");
        }
        if (quads == 0) continue;
        const std::size_t at = std::find(types.begin(), types.end(), kQuad4) - types.begin();
        std::vector<std::array<Index, 4>> plane;
        appendElements<4>(source, nodeTags[at], ids, plane);
        mesh.volumes.push_back(
            {tag, static_cast<Index>(mesh.hexes.size()), static_cast<Index>(quads)});
        for (auto q : plane) {
            const auto& x = mesh.nodes;
            const Vec3 d02 = x[q[2]] - x[q[0]], d13 = x[q[3]] - x[q[1]];
            if (d02[0] * d13[1] - d02[1] * d13[0] < 0.0) std::swap(q[1], q[3]);
            mesh.hexes.push_back({q[0], q[1], q[2], q[3], q[0] + planeNodes, q[1] + planeNodes,
                                  q[2] + planeNodes, q[3] + planeNodes});
        }
        mesh.hexTags.insert(mesh.hexTags.end(), elementTags[at].begin(), elementTags[at].end());
    }
    mesh.dimension = 2;
}

}  // namespace

HexMesh readHexMesh(const std::filesystem::path& input, const MeshReadOptions& options,
                    std::vector<std::string>& warnings) {
    const std::string source = input.string();
    std::error_code ec;
    if (!std::filesystem::exists(input, ec)) throw InputError(source + ": no such file");
    if (!std::filesystem::is_regular_file(input, ec)) throw InputError(source + ": not a file");
    std::string ext = input.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext != ".geo" && ext != ".msh") {
        throw InputError(source + ": unsupported input '" + ext +
                         "' (expected a .geo or .msh file)");
    }
    if (ext == ".msh" && !options.parameters.empty()) {
        throw InputError(source + ": parameters (--set) apply to .geo files only");
    }

    const ParameterWrapper wrapper(input, options.parameters);
    GmshSession session;
    try {
        gmsh::open(wrapper.path().string());
    } catch (const std::string& e) {
        throw InputError(source + ": gmsh cannot read it: " + gmshReason(e));
    } catch (const std::exception& e) {  // gmsh's parser on a damaged file (length_error, …)
        throw InputError(source + ": gmsh cannot read it (" + e.what() + ")");
    }
    std::vector<std::string> log;
    gmsh::logger::get(log);
    checkParameters(input, options.parameters, log);
    collectWarnings(log, warnings);
    if (const std::string error = firstError(log); !error.empty()) {
        throw InputError(source + ": gmsh cannot read it: " + error);
    }
    gmsh::logger::stop();  // a fresh log for meshing
    gmsh::logger::start();
    if (ext == ".geo") {
        try {
            // A model with surfaces but no volumes is a 2-D layout: meshed in 2-D.
            gmsh::vectorpair volumes, surfaces;
            gmsh::model::getEntities(volumes, 3);
            gmsh::model::getEntities(surfaces, 2);
            const int meshDimension = volumes.empty() && !surfaces.empty() ? 2 : 3;
            // Curves first: their cell counts tell the mesh's size before gmsh allocates it
            // (generate(2 or 3) then keeps them).
            gmsh::model::mesh::generate(1);
            checkMeshSize(source, meshDimension, warnings);
            gmsh::model::mesh::generate(meshDimension);
        } catch (const std::string& e) {
            throw MeshError(source + ": gmsh cannot mesh it: " + gmshReason(e));
        }
        std::vector<std::string> meshLog;
        gmsh::logger::get(meshLog);
        collectWarnings(meshLog, warnings);
        if (const std::string error = firstError(meshLog); !error.empty()) {
            throw MeshError(source + ": gmsh cannot mesh it: " + error);
        }
    }

    HexMesh mesh;
    mesh.source = source;
    try {
        std::vector<std::size_t> tags;
        std::vector<double> coords, parametric;
        gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
        const NodeIds ids(tags, coords, mesh.nodes);
        tags = {};
        coords = {};
        readVolumes(source, ids, mesh);
        const auto [planeElements, stray] = countPlaneElements(ids, mesh);
        if (!mesh.hexes.empty() && stray >= 0) {
            throw MeshError(source + ": the mesh mixes 2-D and 3-D elements (surface " +
                            std::to_string(stray) +
                            " is meshed but bounds no hexahedron); convert a 3-D mesh of "
                            "hexahedra or a 2-D mesh of quadrangles, not both");
        }
        if (mesh.hexes.empty() && planeElements > 0) readSurfacesAsSlab(source, ids, mesh);
        readGroups(source, ids, mesh, warnings);
    } catch (const std::string& e) {
        throw MeshError(source + ": gmsh: " + gmshReason(e));
    }
    if (mesh.hexes.empty()) {
        throw MeshError(source +
                        ": the mesh has no hexahedra or quadrangles (no 2-D or 3-D elements" +
                        std::string(ext == ".geo" ? " after meshing: does the file define "
                                                    "volumes or surfaces?)"
                                                  : "; was it meshed, gmsh -3 or gmsh -2?)"));
    }
    return mesh;
}

}  // namespace gsph::preproc
