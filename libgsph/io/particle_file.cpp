// SPDX-License-Identifier: MIT
#include "io/particle_file.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/child_process.hpp"
#include "io/hdf5_file.hpp"

namespace gsph {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(sizeof(std::array<Index, 3>) == 3 * sizeof(Index), "index triples must be packed");

void invalid(const std::string& what) {
    throw InputError("invalid particle data: " + what);
}

bool validSetName(const std::string& name) {
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

void validateSpaces(const ParticleFile& f) {
    if (f.dimension != 2 && f.dimension != 3)
        invalid("dimension " + std::to_string(f.dimension) + " is neither 2 nor 3");
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        const LatticeSpace& sp = f.spaces[s];
        if (!(sp.dtheta > 0.0) || !std::isfinite(sp.dtheta)) {
            invalid("space " + std::to_string(s) + " has a non-positive dtheta");
        }
        for (int c : sp.cells) {
            if (c < 1) invalid("space " + std::to_string(s) + " has an empty cell range");
        }
        if (f.dimension == 2 && (sp.cells[2] != 1 || sp.periodic[2]))
            invalid("space " + std::to_string(s) +
                    " of a 2-D file has more than one cell along "
                    "its third index");
    }
}

/// Checks the per-particle arrays; returns the body of each space (−1 if it has no particle).
std::vector<Index> validateOrdering(const ParticleFile& f) {
    const auto n = static_cast<std::size_t>(f.size());
    const auto spaces = static_cast<Index>(f.spaces.size());
    const auto bodies = static_cast<Index>(f.bodies.size());
    std::vector<Index> bodyOfSpace(f.spaces.size(), -1);
    for (std::size_t a = 0; a < n; ++a) {
        const Index s = f.space[a], b = f.body[a];
        if (s < 0 || s >= spaces) invalid("particle " + std::to_string(a) + ": bad space id");
        if (b < 0 || b >= bodies) invalid("particle " + std::to_string(a) + ": bad body id");
        if (bodyOfSpace[s] == -1) bodyOfSpace[s] = b;
        if (bodyOfSpace[s] != b) invalid("space " + std::to_string(s) + " spans two bodies");
        if (a > 0) {
            const Index sp = f.space[a - 1], bp = f.body[a - 1];
            if (b < bp || (b == bp && s < sp)) {
                invalid("particles are not sorted by body, then space (at " + std::to_string(a) +
                        ")");
            }
        }
        if (!(f.volume[a] > 0.0) || !std::isfinite(f.volume[a])) {
            invalid("particle " + std::to_string(a) + " has a non-positive volume");
        }
        if (!f.X[a].allFinite() || !f.theta[a].allFinite()) {
            invalid("particle " + std::to_string(a) + " has a non-finite position");
        }
        if (f.dimension == 2 && (f.X[a][2] != 0.0 || f.theta[a][2] != 0.0))
            invalid("particle " + std::to_string(a) + " of a 2-D file has X_z or theta_z not 0");
        if (!f.latticeIndex.empty()) {
            const auto& cells = f.spaces[static_cast<std::size_t>(s)].cells;
            for (int d = 0; d < 3; ++d) {
                const Index i = f.latticeIndex[a][static_cast<std::size_t>(d)];
                if (i < 0 || i >= cells[static_cast<std::size_t>(d)]) {
                    invalid("particle " + std::to_string(a) + " lies outside its space's cells");
                }
            }
        }
    }
    return bodyOfSpace;
}

/// /spaces/cells against the particles (docs/formats.md): a particle occupies one cell of its
/// space, so a space has at most n_i n_j n_k particles, and exactly that many when there is no
/// /particles/lattice_index (the particle's rank in its space is then its cell). Cell ids are
/// Index values, so a space may not have more cells than Index can count. Products in 64 bits.
void validateCellCounts(const ParticleFile& f) {
    std::vector<std::int64_t> particles(f.spaces.size(), 0);
    for (const Index s : f.space) ++particles[static_cast<std::size_t>(s)];
    constexpr std::int64_t kMaxCells = std::numeric_limits<Index>::max();
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        const auto& c = f.spaces[s].cells;  // each ≥ 1 (validateSpaces)
        const std::string cells = "space " + std::to_string(s) + ": /spaces/cells " +
                                  std::to_string(c[0]) + "x" + std::to_string(c[1]) + "x" +
                                  std::to_string(c[2]);
        std::int64_t product = std::int64_t{c[0]} * c[1];  // < 2^62
        if (product <= kMaxCells) product *= c[2];
        if (product > kMaxCells) {
            invalid(cells + " has more cells than a space can hold (" + std::to_string(kMaxCells) +
                    ")");
        }
        const std::string counts = " = " + std::to_string(product) + " cells for " +
                                   std::to_string(particles[s]) + " particles";
        if (particles[s] > product) invalid(cells + counts + " (at most one per cell)");
        if (f.latticeIndex.empty() && particles[s] != product) {
            invalid(cells + counts +
                    " (without /particles/lattice_index every cell holds one particle)");
        }
    }
}

/// The overset entries and the transient flags (DESIGN §6; docs/formats.md).
void validateOverset(const ParticleFile& f, const std::vector<Index>& bodyOfSpace) {
    const OversetEntries& o = f.overset;
    const std::size_t m = o.size(), n = f.X.size();
    if (o.space.size() != m || o.theta.size() != m || o.omega.size() != m) {
        invalid("overset arrays differ in length");
    }
    if (f.transient.empty()) {
        if (m != 0) invalid("overset entries without /particles/transient flags");
        return;
    }
    if (f.transient.size() != n) invalid("transient flags have the wrong length");
    if (!(o.kappa > 0.0) || !std::isfinite(o.kappa)) invalid("overset kappa must be positive");
    std::vector<std::int8_t> hasEntry(n, 0);
    for (std::size_t e = 0; e < m; ++e) {
        const std::string entry = "overset entry " + std::to_string(e);
        const Index a = o.particle[e], s = o.space[e];
        if (a < 0 || static_cast<std::size_t>(a) >= n) invalid(entry + ": particle out of range");
        if (s < 0 || static_cast<std::size_t>(s) >= f.spaces.size()) {
            invalid(entry + ": space out of range");
        }
        if (s == f.space[a]) invalid(entry + ": the particle's own home space");
        if (bodyOfSpace[s] != f.body[a]) invalid(entry + ": a space of another body");
        if (e > 0 && (s < o.space[e - 1] || (s == o.space[e - 1] && a <= o.particle[e - 1]))) {
            invalid(entry + ": entries are not sorted by (space, particle) and unique");
        }
        if (!(o.omega[e] > 0.0) || !std::isfinite(o.omega[e])) {
            invalid(entry + ": omega is not positive and finite");
        }
        const LatticeSpace& sp = f.spaces[s];
        const double reach = 2.0 * o.kappa * sp.dtheta;  // the selection radius 2κΔθ
        for (std::size_t d = 0; d < 3; ++d) {
            const double t = o.theta[e][d], extent = sp.cells[d] * sp.dtheta;
            if (!std::isfinite(t) || t < -reach || t > extent + reach) {
                invalid(entry + ": theta is not finite or lies beyond 2 kappa dtheta of space " +
                        std::to_string(s));
            }
        }
        if (f.dimension == 2 && o.theta[e][2] != 0.0)
            invalid(entry + ": theta_z of a 2-D file not 0");
        hasEntry[a] = 1;
    }
    if (hasEntry != f.transient) {
        invalid(
            "transient flags do not match the overset entries (1 exactly for the particles "
            "that have an entry)");
    }
}

}  // namespace

std::array<std::size_t, 3> nodeExtent(const LatticeSpace& space) {
    std::array<std::size_t, 3> m{};
    for (std::size_t d = 0; d < 3; ++d)
        m[d] = static_cast<std::size_t>(space.cells[d]) + (space.periodic[d] ? 0 : 1);
    return m;
}

std::size_t nodeCount(const std::vector<LatticeSpace>& spaces) {
    std::size_t total = 0;
    for (const LatticeSpace& s : spaces) {
        const auto m = nodeExtent(s);
        total += m[0] * m[1] * m[2];
    }
    return total;
}

std::size_t nodeRow(const LatticeSpace& space, int i, int j, int k) {
    const auto m = nodeExtent(space);
    const int ijk[3] = {i, j, k};
    std::size_t u[3];
    for (std::size_t d = 0; d < 3; ++d) {
        const auto md = static_cast<long>(m[d]);
        u[d] = static_cast<std::size_t>(((ijk[d] % md) + md) % md);
    }
    return u[0] + m[0] * (u[1] + m[1] * u[2]);
}

std::vector<std::array<Index, 3>> latticeCells(const ParticleFile& f) {
    if (!f.latticeIndex.empty()) return f.latticeIndex;
    std::vector<std::array<Index, 3>> cells(f.X.size());
    std::size_t first = 0;  // the space's first particle (particles are sorted by space)
    for (std::size_t a = 0; a < cells.size(); ++a) {
        if (a > 0 && f.space[a] != f.space[a - 1]) first = a;
        const auto& n = f.spaces[static_cast<std::size_t>(f.space[a])].cells;
        const auto r = static_cast<Index>(a - first);
        cells[a] = {r % n[0], r / n[0] % n[1], r / (n[0] * n[1])};
    }
    return cells;
}

std::vector<Vec3> sweptSetAreas(const ParticleFile& f, const std::string& set) {
    if (f.dimension != 2) throw InputError("swept set areas need a 2-D particle file");
    const auto members = f.sets.find(set);
    const auto areas = f.setAreas.find(set);
    if (members == f.sets.end() || areas == f.setAreas.end())
        throw InputError("set '" + set + "' has no face areas");
    constexpr double kTwoPi = 2.0 * 3.141592653589793238462643383279502884;
    std::vector<Vec3> swept(areas->second.size());
    std::vector<std::size_t> firstNode(f.spaces.size() + 1, 0);
    for (std::size_t s = 0; s < f.spaces.size(); ++s)
        firstNode[s + 1] = firstNode[s] + nodeCount({f.spaces[s]});
    const std::vector<std::array<Index, 3>> cells =
        f.nodes.empty() ? std::vector<std::array<Index, 3>>{} : latticeCells(f);
    for (std::size_t k = 0; k < swept.size(); ++k) {
        const auto a = static_cast<std::size_t>(members->second[k]);
        const Vec3& A = areas->second[k];
        swept[k] = kTwoPi * f.X[a][0] * A;  // the member's own radius, unless the edges split A
        if (f.nodes.empty()) continue;
        const auto s = static_cast<std::size_t>(f.space[a]);
        const auto& c = cells[a];
        // The cell's corners in order around it; edge e joins corner e and corner e + 1.
        const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        Vec3 P[4];
        for (int e = 0; e < 4; ++e)
            P[e] = f.nodes[firstNode[s] +
                           nodeRow(f.spaces[s], c[0] + corner[e][0], c[1] + corner[e][1], 0)];
        Vec3 edgeArea[4], edgeSwept[4];
        for (int e = 0; e < 4; ++e) {
            const Vec3 d = P[(e + 1) % 4] - P[e], mid = 0.5 * (P[e] + P[(e + 1) % 4]);
            Vec3 n(d[1], -d[0], 0.0);  // |n| = |d|: the edge's area per metre of depth
            if (n.dot(mid - f.X[a]) < 0.0) n = -n;
            edgeArea[e] = n;
            edgeSwept[e] = kTwoPi * mid[0] * n;
        }
        double best = 1e-9 * A.norm();
        for (int subset = 1; subset < 16; ++subset) {
            Vec3 sum = Vec3::Zero(), sweptSum = Vec3::Zero();
            for (int e = 0; e < 4; ++e)
                if (subset >> e & 1) sum += edgeArea[e], sweptSum += edgeSwept[e];
            const double mismatch = (sum - A).norm();
            if (mismatch <= best) best = mismatch, swept[k] = sweptSum;
        }
    }
    return swept;
}

void validateParticleFile(const ParticleFile& f) {
    const auto n = static_cast<std::size_t>(f.size());
    if (f.theta.size() != n || f.volume.size() != n || f.space.size() != n || f.body.size() != n) {
        invalid("per-particle arrays differ in length");
    }
    if (!f.latticeIndex.empty() && f.latticeIndex.size() != n) {
        invalid("lattice_index has the wrong length");
    }
    validateSpaces(f);
    const std::vector<Index> bodyOfSpace = validateOrdering(f);
    validateCellCounts(f);
    validateOverset(f, bodyOfSpace);
    for (const auto& [name, members] : f.sets) {
        if (!validSetName(name)) invalid("set name '" + name + "' is not a valid HDF5 name");
        for (std::size_t k = 0; k < members.size(); ++k) {
            if (members[k] < 0 || static_cast<std::size_t>(members[k]) >= n) {
                invalid("set '" + name + "' holds an index out of range");
            }
            if (k > 0 && members[k] <= members[k - 1]) {
                invalid("set '" + name + "' is not sorted and unique");
            }
        }
    }
    if (!f.nodes.empty()) {
        if (f.nodes.size() != nodeCount(f.spaces))
            invalid("/spaces/nodes has " + std::to_string(f.nodes.size()) +
                    " rows, the spaces' lattices have " + std::to_string(nodeCount(f.spaces)) +
                    " nodes");
        for (const Vec3& X : f.nodes)
            if (!X.allFinite()) invalid("a node position in /spaces/nodes is not finite");
    }
    for (const auto& [name, areas] : f.setAreas) {
        const auto set = f.sets.find(name);
        if (set == f.sets.end()) invalid("face areas of set '" + name + "', which does not exist");
        if (areas.size() != set->second.size())
            invalid("set '" + name + "' has " + std::to_string(areas.size()) + " face areas for " +
                    std::to_string(set->second.size()) + " particles");
        for (const Vec3& A : areas)
            if (!A.allFinite()) invalid("set '" + name + "' has a face area that is not finite");
    }
}

namespace {

void writeOverset(h5::File& h5, const ParticleFile& f) {
    const OversetEntries& o = f.overset;
    const std::size_t m = o.size();
    h5.write("/particles/transient", f.transient.data(), {f.transient.size()});
    h5.createGroup("/overset");
    h5.write("/overset/particle", o.particle.data(), {m});
    h5.write("/overset/space", o.space.data(), {m});
    h5.write("/overset/theta", o.theta.empty() ? nullptr : o.theta.front().data(), {m, 3});
    h5.setAttribute("/overset/theta", "units", std::string("1"));
    h5.write("/overset/omega", o.omega.data(), {m});
    h5.write("/overset/kappa", &o.kappa, {1});
}

}  // namespace

void writeParticleFile(const std::filesystem::path& path, const ParticleFile& f) {
    validateParticleFile(f);
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        h5::File h5(temp, h5::File::Mode::Create);
        const std::size_t n = f.X.size();
        h5.setAttribute("/", "format", std::string(kParticleFormat));
        h5.setAttribute(
            "/", "format_version",
            std::to_string(kParticleFormatMajor) + "." + std::to_string(kParticleFormatMinor));
        writeProvenance(h5, f.provenance);

        h5.write("/particles/X", f.X.empty() ? nullptr : f.X.front().data(), {n, 3});
        h5.setAttribute("/particles/X", "units", std::string("m"));
        h5.write("/particles/theta", f.theta.empty() ? nullptr : f.theta.front().data(), {n, 3});
        h5.setAttribute("/particles/theta", "units", std::string("1"));
        h5.write("/particles/volume", f.volume.data(), {n});
        h5.setAttribute("/particles/volume", "units", std::string("m^3"));
        h5.write("/particles/space", f.space.data(), {n});
        h5.write("/particles/body", f.body.data(), {n});
        if (!f.latticeIndex.empty()) {
            h5.write("/particles/lattice_index", f.latticeIndex.front().data(), {n, 3});
        }

        const std::size_t spaces = f.spaces.size();
        std::vector<std::int32_t> cells;
        std::vector<std::int8_t> periodic;
        std::vector<double> dtheta;
        for (const LatticeSpace& s : f.spaces) {
            for (int d = 0; d < 3; ++d) {
                cells.push_back(s.cells[static_cast<std::size_t>(d)]);
                periodic.push_back(s.periodic[static_cast<std::size_t>(d)] ? 1 : 0);
            }
            dtheta.push_back(s.dtheta);
        }
        const std::int32_t dimension = f.dimension;
        h5.write("/dimension", &dimension, {1});
        h5.write("/spaces/cells", cells.data(), {spaces, 3});
        h5.write("/spaces/periodic", periodic.data(), {spaces, 3});
        h5.write("/spaces/dtheta", dtheta.data(), {spaces});
        if (!f.nodes.empty()) {
            h5.write("/spaces/nodes", f.nodes.front().data(), {f.nodes.size(), 3});
            h5.setAttribute("/spaces/nodes", "units", std::string("m"));
        }

        std::vector<std::string> names;
        std::vector<std::int32_t> tags;
        for (const BodyInfo& b : f.bodies) {
            names.push_back(b.name);
            tags.push_back(b.sourceTag);
        }
        h5.writeStrings("/bodies/name", names);
        h5.write("/bodies/source_tag", tags.data(), {tags.size()});

        h5.createGroup("/sets");
        for (const auto& [name, members] : f.sets) {
            h5.write("/sets/" + name, members.data(), {members.size()});
        }
        if (!f.setAreas.empty()) {
            h5.createGroup("/set_areas");
            for (const auto& [name, areas] : f.setAreas) {
                h5.write("/set_areas/" + name, areas.empty() ? nullptr : areas.front().data(),
                         {areas.size(), 3});
                h5.setAttribute("/set_areas/" + name, "units", std::string("m^2"));
            }
        }
        if (!f.transient.empty()) writeOverset(h5, f);
        h5.close(path);
    });
}

namespace {

/// Checks that a dataset has shape {n} (cols == 0) or {n, cols}; returns n.
std::size_t expectShape(const h5::File& h5, const std::string& path,
                        const std::vector<std::size_t>& dims, std::size_t cols) {
    const bool ok = cols == 0 ? dims.size() == 1 : (dims.size() == 2 && dims[1] == cols);
    if (!ok) {
        throw IoError(h5.name() + ": dataset " + path + " has the wrong shape (expected " +
                      (cols == 0 ? std::string("N") : "N×" + std::to_string(cols)) + ")");
    }
    return dims[0];
}

std::vector<Vec3> readVec3(const h5::File& h5, const std::string& path, std::size_t n) {
    std::vector<std::size_t> dims;
    const std::vector<double> flat = h5.read<double>(path, dims);
    if (expectShape(h5, path, dims, 3) != n) {
        throw IoError(h5.name() + ": dataset " + path + " has the wrong length");
    }
    std::vector<Vec3> out(n);
    for (std::size_t a = 0; a < n; ++a)
        out[a] = Vec3(flat[3 * a], flat[3 * a + 1], flat[3 * a + 2]);
    return out;
}

template <class T>
std::vector<T> readColumn(const h5::File& h5, const std::string& path, std::size_t n) {
    std::vector<std::size_t> dims;
    std::vector<T> values = h5.read<T>(path, dims);
    if (expectShape(h5, path, dims, 0) != n) {
        throw IoError(h5.name() + ": dataset " + path + " has the wrong length");
    }
    return values;
}

void checkFormat(const h5::File& h5) {
    if (!h5.hasAttribute("/", "format") || h5.stringAttribute("/", "format") != kParticleFormat) {
        throw IoError(h5.name() + ": not a " + std::string(kParticleFormat) +
                      " file (root attribute 'format' missing or different)");
    }
    const std::string version = h5.stringAttribute("/", "format_version");
    const std::size_t dot = version.find('.');
    const std::string major = version.substr(0, dot);
    if (major != std::to_string(kParticleFormatMajor)) {
        throw IoError(h5.name() + ": format version " + version +
                      " is not supported (this build "
                      "reads " +
                      std::to_string(kParticleFormatMajor) + ".x)");
    }
}

/// /particles/transient and /overset (format 1.1); a 1.0 file has neither.
void readOverset(const h5::File& h5, ParticleFile& f) {
    const std::size_t n = f.X.size();
    if (h5.exists("/particles/transient")) {
        f.transient = readColumn<std::int8_t>(h5, "/particles/transient", n);
    }
    if (!h5.exists("/overset")) return;
    std::vector<std::size_t> dims;
    OversetEntries& o = f.overset;
    o.particle = h5.read<std::int32_t>("/overset/particle", dims);
    const std::size_t m = expectShape(h5, "/overset/particle", dims, 0);
    o.space = readColumn<std::int32_t>(h5, "/overset/space", m);
    o.theta = readVec3(h5, "/overset/theta", m);
    o.omega = readColumn<double>(h5, "/overset/omega", m);
    o.kappa = readColumn<double>(h5, "/overset/kappa", 1)[0];
}

}  // namespace

ParticleFile readParticleFile(const std::filesystem::path& path) {
    h5::File h5(path, h5::File::Mode::ReadOnly);
    checkFormat(h5);
    ParticleFile f;
    f.provenance = readProvenance(h5);

    std::vector<std::size_t> dims;
    f.volume = h5.read<double>("/particles/volume", dims);
    const std::size_t n = expectShape(h5, "/particles/volume", dims, 0);
    f.X = readVec3(h5, "/particles/X", n);
    f.theta = readVec3(h5, "/particles/theta", n);
    f.space = readColumn<std::int32_t>(h5, "/particles/space", n);
    f.body = readColumn<std::int32_t>(h5, "/particles/body", n);
    if (h5.exists("/particles/lattice_index")) {
        const std::vector<std::int32_t> flat =
            h5.read<std::int32_t>("/particles/lattice_index", dims);
        if (expectShape(h5, "/particles/lattice_index", dims, 3) != n) {
            throw IoError(h5.name() + ": dataset /particles/lattice_index has the wrong length");
        }
        f.latticeIndex.resize(n);
        for (std::size_t a = 0; a < n; ++a) {
            f.latticeIndex[a] = {flat[3 * a], flat[3 * a + 1], flat[3 * a + 2]};
        }
    }

    if (h5.exists("/dimension")) f.dimension = readColumn<std::int32_t>(h5, "/dimension", 1)[0];
    const std::vector<double> dtheta = h5.read<double>("/spaces/dtheta", dims);
    const std::size_t spaces = expectShape(h5, "/spaces/dtheta", dims, 0);
    const std::vector<std::int32_t> cells = h5.read<std::int32_t>("/spaces/cells", dims);
    if (expectShape(h5, "/spaces/cells", dims, 3) != spaces) {
        throw IoError(h5.name() + ": /spaces/cells and /spaces/dtheta differ in length");
    }
    const std::vector<std::int8_t> periodic = h5.read<std::int8_t>("/spaces/periodic", dims);
    if (expectShape(h5, "/spaces/periodic", dims, 3) != spaces) {
        throw IoError(h5.name() + ": /spaces/periodic and /spaces/dtheta differ in length");
    }
    f.spaces.resize(spaces);
    for (std::size_t s = 0; s < spaces; ++s) {
        f.spaces[s].dtheta = dtheta[s];
        for (std::size_t d = 0; d < 3; ++d) {
            f.spaces[s].cells[d] = cells[3 * s + d];
            f.spaces[s].periodic[d] = periodic[3 * s + d] != 0;
        }
    }

    if (h5.exists("/spaces/nodes")) {  // since 1.3
        // Checked against the spaces before anything is allocated from its length.
        std::vector<std::size_t> nodeDims;
        const std::vector<double> flat = h5.read<double>("/spaces/nodes", nodeDims);
        const std::size_t expected = nodeCount(f.spaces);
        if (expectShape(h5, "/spaces/nodes", nodeDims, 3) != expected)
            throw IoError(h5.name() + ": /spaces/nodes has " + std::to_string(nodeDims[0]) +
                          " rows, the spaces' lattices have " + std::to_string(expected) +
                          " nodes");
        f.nodes.resize(expected);
        for (std::size_t r = 0; r < expected; ++r)
            f.nodes[r] = Vec3(flat[3 * r], flat[3 * r + 1], flat[3 * r + 2]);
    }

    const std::vector<std::string> names = h5.readStrings("/bodies/name");
    const std::vector<std::int32_t> tags =
        readColumn<std::int32_t>(h5, "/bodies/source_tag", names.size());
    for (std::size_t b = 0; b < names.size(); ++b) f.bodies.push_back({names[b], tags[b]});

    if (h5.exists("/sets")) {
        for (const std::string& name : h5.members("/sets")) {
            std::vector<std::int32_t> members = h5.read<std::int32_t>("/sets/" + name, dims);
            if (dims.size() != 1) {
                throw IoError(h5.name() + ": set /sets/" + name + " is not one-dimensional");
            }
            f.sets.emplace(name, std::move(members));
        }
    }
    if (h5.exists("/set_areas")) {
        for (const std::string& name : h5.members("/set_areas")) {
            const auto set = f.sets.find(name);
            if (set == f.sets.end())
                throw IoError(h5.name() + ": /set_areas/" + name + " names no set of /sets");
            f.setAreas.emplace(name, readVec3(h5, "/set_areas/" + name, set->second.size()));
        }
    }

    readOverset(h5, f);

    try {
        validateParticleFile(f);
    } catch (const InputError& e) {
        throw IoError(h5.name() + ": " + e.what());
    }
    return f;
}

ParticleFile readParticleFileIsolated(const std::filesystem::path& path, unsigned deadlineSeconds) {
    const std::string source = path.string();
    const std::string bytes = runInChild(
        source, "the particle-file reader",
        [&](ByteWriter& w) {
            const ParticleFile f = readParticleFile(path);
            w.array(f.X);
            w.array(f.theta);
            w.array(f.volume);
            w.array(f.space);
            w.array(f.body);
            w.array(f.latticeIndex);
            w.array(f.transient);
            w.array(f.overset.particle);
            w.array(f.overset.space);
            w.array(f.overset.theta);
            w.array(f.overset.omega);
            w.value(f.overset.kappa);
            w.array(f.spaces);
            w.array(f.nodes);
            w.value<std::int32_t>(f.dimension);
            w.value<std::uint64_t>(f.bodies.size());
            for (const BodyInfo& b : f.bodies) {
                w.text(b.name);
                w.value(b.sourceTag);
            }
            w.value<std::uint64_t>(f.sets.size());
            for (const auto& [name, members] : f.sets) {
                w.text(name);
                w.array(members);
            }
            w.value<std::uint64_t>(f.setAreas.size());
            for (const auto& [name, areas] : f.setAreas) {
                w.text(name);
                w.array(areas);
            }
            writeProvenance(w, f.provenance);
        },
        [&](const std::string& reason) {
            throw IoError(source + ": the file crashed or hung HDF5's reader (" + reason +
                          "): it is damaged or not a particle file");
        },
        deadlineSeconds > 0 ? deadlineSeconds : fileReadDeadline(path));
    ByteReader r(bytes, source);
    ParticleFile f;
    f.X = r.array<Vec3>();
    f.theta = r.array<Vec3>();
    f.volume = r.array<double>();
    f.space = r.array<Index>();
    f.body = r.array<Index>();
    f.latticeIndex = r.array<std::array<Index, 3>>();
    f.transient = r.array<std::int8_t>();
    f.overset.particle = r.array<Index>();
    f.overset.space = r.array<Index>();
    f.overset.theta = r.array<Vec3>();
    f.overset.omega = r.array<double>();
    f.overset.kappa = r.value<double>();
    f.spaces = r.array<LatticeSpace>();
    f.nodes = r.array<Vec3>();
    f.dimension = r.value<std::int32_t>();
    f.bodies.resize(r.value<std::uint64_t>());
    for (BodyInfo& b : f.bodies) {
        b.name = r.text();
        b.sourceTag = r.value<Index>();
    }
    const auto sets = r.value<std::uint64_t>();
    for (std::uint64_t k = 0; k < sets; ++k) {
        std::string name = r.text();
        f.sets[name] = r.array<Index>();
    }
    const auto areaSets = r.value<std::uint64_t>();
    for (std::uint64_t k = 0; k < areaSets; ++k) {
        std::string name = r.text();
        f.setAreas[name] = r.array<Vec3>();
    }
    f.provenance = readProvenance(r);
    return f;
}

}  // namespace gsph
