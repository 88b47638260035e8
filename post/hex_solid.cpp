// SPDX-License-Identifier: MIT
#include "hex_solid.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "io/child_process.hpp"
#include "io/hdf5_file.hpp"
#include "spaces/hexahedron.hpp"

namespace gsph::post {
namespace {

// Lattice offsets (i, j, k) of the corners in VTK_HEXAHEDRON order.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// The same corners mirrored in k (a left-handed frame).
constexpr int kMirrored[8] = {4, 5, 6, 7, 0, 1, 2, 3};
// Lattice offsets (i, j) of a 2-D cell's corners in VTK_QUAD order, and the same reversed (a
// left-handed frame in the plane).
constexpr int kQuadCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr int kReversed[4] = {0, 3, 2, 1};

using Cell = std::array<int, 3>;

std::string point(const Vec3& X) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", X[0], X[1], X[2]);
    return text;
}

// The particle of each cell of a space (−1: none), cells in lattice order.
struct SpaceCells {
    const LatticeSpace* space = nullptr;
    std::vector<Index> particleAt;
    std::vector<std::pair<Index, Cell>> particles;  // (particle, its cell), in file order

    std::size_t row(const Cell& c) const {
        return static_cast<std::size_t>(c[0]) +
               static_cast<std::size_t>(space->cells[0]) *
                   (static_cast<std::size_t>(c[1]) +
                    static_cast<std::size_t>(space->cells[1]) * static_cast<std::size_t>(c[2]));
    }
    // The particle of the cell c + step·e_d (wrapped along a periodic index), or −1.
    Index neighbour(Cell c, int d, int step) const {
        c[d] += step;
        const int n = space->cells[d];
        if (c[d] < 0 || c[d] >= n) {
            if (!space->periodic[d]) return -1;
            c[d] = (c[d] % n + n) % n;
        }
        return particleAt[row(c)];
    }
};

// Reference node positions of a space estimated from its particles (a file without
// /spaces/nodes): X_n = mean over the cells around n of X_a + M_a (u_n − u_a), M_a = ∂X/∂u by
// differences of the neighbours' X along the lattice. NaN at nodes of no cell.
std::vector<Vec3> estimateNodes(const SpaceCells& sc, const std::vector<Vec3>& X,
                                const std::vector<double>& V) {
    const LatticeSpace& sp = *sc.space;
    const auto m = nodeExtent(sp);
    std::vector<Vec3> sum(m[0] * m[1] * m[2], Vec3::Zero());
    std::vector<int> count(sum.size(), 0);
    for (const auto& [a, c] : sc.particles) {
        Mat3 M = Mat3::Zero();
        bool have[3] = {false, false, false};
        for (int d = 0; d < 3; ++d) {
            const Index plus = sc.neighbour(c, d, 1), minus = sc.neighbour(c, d, -1);
            if (plus >= 0 && minus >= 0 && plus != minus && plus != a && minus != a) {
                M.col(d) = 0.5 * (X[plus] - X[minus]);
            } else if (plus >= 0 && plus != a) {
                M.col(d) = X[plus] - X[a];
            } else if (minus >= 0 && minus != a) {
                M.col(d) = X[a] - X[minus];
            } else {
                continue;
            }
            have[d] = true;
        }
        const int missing = !have[0] + !have[1] + !have[2];
        if (missing == 1) {  // one cell thick along d: the normal of the others, det M = V_a
            const int d = !have[0] ? 0 : (!have[1] ? 1 : 2);
            const Vec3 normal = M.col((d + 1) % 3).cross(M.col((d + 2) % 3));
            if (normal.squaredNorm() > 0.0) M.col(d) = V[a] / normal.squaredNorm() * normal;
        }
        const double h = std::cbrt(V[a]);  // a lone particle or row: a cube of its volume
        for (int d = 0; d < 3; ++d)
            if (M.col(d).squaredNorm() == 0.0) M.col(d) = h * Vec3::Unit(d);
        for (const auto& k : kCorner) {
            const Vec3 offset(k[0] - 0.5, k[1] - 0.5, k[2] - 0.5);
            const std::size_t r = nodeRow(sp, c[0] + k[0], c[1] + k[1], c[2] + k[2]);
            sum[r] += X[a] + M * offset;
            ++count[r];
        }
    }
    for (std::size_t r = 0; r < sum.size(); ++r)
        sum[r] = count[r] > 0 ? Vec3(sum[r] / count[r])
                              : Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    return sum;
}

}  // namespace

double hexahedronVolume(const std::array<Vec3, 8>& x) {
    return hexVolume({x[0], x[1], x[3], x[2], x[4], x[5], x[7], x[6]});  // VTK → corner bits
}

double hexahedraVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes) {
    double total = 0.0;
    for (const auto& hex : piece.hexes) {
        std::array<Vec3, 8> x;
        for (int c = 0; c < 8; ++c) x[c] = nodes[static_cast<std::size_t>(hex[c])];
        total += hexahedronVolume(x);
    }
    return total;
}

double quadrilateralArea(const std::array<Vec3, 4>& x) {
    // Half the cross product of the diagonals: the shoelace formula of the four corners.
    const Vec3 d02 = x[2] - x[0], d13 = x[3] - x[1];
    return 0.5 * (d02[0] * d13[1] - d02[1] * d13[0]);
}

double quadrilateralsArea(const SolidPiece& piece, const std::vector<Vec3>& nodes) {
    double total = 0.0;
    for (const auto& quad : piece.quads) {
        std::array<Vec3, 4> x;
        for (int c = 0; c < 4; ++c) x[c] = nodes[static_cast<std::size_t>(quad[c])];
        total += quadrilateralArea(x);
    }
    return total;
}

double cellsVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes) {
    return hexahedraVolume(piece, nodes) + quadrilateralsArea(piece, nodes);
}

HexSolid::HexSolid(const ParticleFile& f, const std::vector<Vec3>& X, const std::string& source) {
    const std::size_t n = X.size();
    if (static_cast<std::size_t>(f.size()) != n)
        throw InputError(source + ": " + std::to_string(f.size()) +
                         " particles, the run's snapshots have " + std::to_string(n) +
                         " (not the run's particle file)");
    double scale = 0.0;
    for (const Vec3& p : X) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    for (std::size_t a = 0; a < n; ++a)
        if (!((f.X[a] - X[a]).norm() <= 1e-9 * scale))
            throw InputError(source + ": particle " + std::to_string(a) + " lies at " +
                             point(f.X[a]) + ", in the run's snapshots at " + point(X[a]) +
                             " (not the run's particle file)");
    volume_ = f.volume;
    for (double V : volume_) particleVolume_ += V;
    estimated_ = f.nodes.empty();
    dimension_ = f.dimension;

    // The particles of each space and their cells (lattice_index, or the rank in the space).
    std::vector<SpaceCells> spaces(f.spaces.size());
    const std::vector<std::array<Index, 3>> cellOf = latticeCells(f);
    for (std::size_t s = 0; s < spaces.size(); ++s) {
        const auto& c = f.spaces[s].cells;
        spaces[s].space = &f.spaces[s];
        spaces[s].particleAt.assign(static_cast<std::size_t>(c[0]) * c[1] * c[2], -1);
    }
    for (std::size_t a = 0; a < n; ++a) {
        const auto s = static_cast<std::size_t>(f.space[a]);
        SpaceCells& sc = spaces[s];
        const Cell c = {cellOf[a][0], cellOf[a][1], cellOf[a][2]};
        Index& at = sc.particleAt[sc.row(c)];
        if (at >= 0)
            throw InputError(source + ": particles " + std::to_string(at) + " and " +
                             std::to_string(a) + " are in one cell of space " + std::to_string(s));
        at = static_cast<Index>(a);
        sc.particles.emplace_back(static_cast<Index>(a), c);
    }

    std::size_t firstNode = 0;  // of the space in f.nodes
    for (std::size_t s = 0; s < spaces.size(); ++s) {
        const SpaceCells& sc = spaces[s];
        const LatticeSpace& sp = f.spaces[s];
        const auto m = nodeExtent(sp);
        const std::size_t rows = m[0] * m[1] * m[2];
        std::vector<Vec3> reference;
        if (estimated_ && !sc.particles.empty()) reference = estimateNodes(sc, f.X, f.volume);
        if (!estimated_)
            reference.assign(f.nodes.begin() + static_cast<std::ptrdiff_t>(firstNode),
                             f.nodes.begin() + static_cast<std::ptrdiff_t>(firstNode + rows));
        firstNode += rows;
        if (sc.particles.empty()) continue;

        SolidPiece piece;
        piece.space = static_cast<Index>(s);
        piece.body = f.body[static_cast<std::size_t>(sc.particles.front().first)];
        std::vector<Index> idOfRow(rows, -1);
        // The piece's id of lattice node (i, j, k), added at its first use.
        auto nodeId = [&](int i, int j, int k) {
            const std::size_t r = nodeRow(sp, i, j, k);
            if (idOfRow[r] < 0) {
                idOfRow[r] = static_cast<Index>(piece.nodeX.size());
                Vec3 at = reference[r];
                // The layout's plane: the mid-plane of estimated nodes (z = ±½), z = 0 of given.
                if (dimension_ == 2) at[2] = 0.0;
                piece.nodeX.push_back(at);
                piece.cellsAround.push_back(0);
            }
            ++piece.cellsAround[static_cast<std::size_t>(idOfRow[r])];
            return idOfRow[r];
        };
        for (const auto& [a, c] : sc.particles) {
            if (dimension_ == 2) {
                std::array<Index, 4> quad;
                for (int k = 0; k < 4; ++k)
                    quad[k] = nodeId(c[0] + kQuadCorner[k][0], c[1] + kQuadCorner[k][1], 0);
                piece.quads.push_back(quad);
            } else {
                std::array<Index, 8> hex;
                for (int k = 0; k < 8; ++k)
                    hex[k] =
                        nodeId(c[0] + kCorner[k][0], c[1] + kCorner[k][1], c[2] + kCorner[k][2]);
                piece.hexes.push_back(hex);
            }
            piece.particle.push_back(a);
        }
        // A left-handed lattice frame (det ∂X/∂u < 0) would turn every cell inside out.
        if (hexahedraVolume(piece, piece.nodeX) < 0.0)
            for (auto& hex : piece.hexes) {
                const std::array<Index, 8> h = hex;
                for (int k = 0; k < 8; ++k) hex[k] = h[kMirrored[k]];
            }
        if (quadrilateralsArea(piece, piece.nodeX) < 0.0)
            for (auto& quad : piece.quads) {
                const std::array<Index, 4> q = quad;
                for (int k = 0; k < 4; ++k) quad[k] = q[kReversed[k]];
            }
        pieces_.push_back(std::move(piece));
    }
}

std::size_t HexSolid::cells() const {
    return hexahedra() + quadrilaterals();
}

std::size_t HexSolid::hexahedra() const {
    std::size_t total = 0;
    for (const SolidPiece& p : pieces_) total += p.hexes.size();
    return total;
}

std::size_t HexSolid::quadrilaterals() const {
    std::size_t total = 0;
    for (const SolidPiece& p : pieces_) total += p.quads.size();
    return total;
}

double HexSolid::referenceVolume() const {
    double total = 0.0;
    for (const SolidPiece& p : pieces_) total += cellsVolume(p, p.nodeX);
    return total;
}

double HexSolid::particleVolume(const Snapshot& s) const {
    double total = 0.0;
    for (std::size_t a = 0; a < volume_.size() && a < s.state.F.size(); ++a) {
        const Mat3& F = s.state.F[a];
        total += volume_[a] *
                 (dimension_ == 2 ? F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0) : F.determinant());
    }
    return total;
}

double HexSolid::currentVolume(const Snapshot& s) const {
    double total = 0.0;
    for (const SolidPiece& p : pieces_) total += cellsVolume(p, currentNodes(p, s));
    return total;
}

std::vector<Vec3> HexSolid::currentNodes(const SolidPiece& piece, const Snapshot& s) const {
    std::vector<Vec3> x(piece.nodeX.size(), Vec3::Zero());
    auto addCell = [&](std::size_t cell, const auto& corners) {
        const auto a = static_cast<std::size_t>(piece.particle[cell]);
        for (const Index node : corners) {
            const auto i = static_cast<std::size_t>(node);
            x[i] += s.state.x[a] + s.state.F[a] * (piece.nodeX[i] - s.X[a]);
        }
    };
    for (std::size_t h = 0; h < piece.hexes.size(); ++h) addCell(h, piece.hexes[h]);
    for (std::size_t q = 0; q < piece.quads.size(); ++q) addCell(q, piece.quads[q]);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] /= piece.cellsAround[i];
    return x;
}

namespace {

// The reference section's size (the largest extent of its nodes), for the axis tolerance.
double sectionSize(const SolidPiece& piece) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Vec3& X : piece.nodeX) {
        lo = lo.cwiseMin(X);
        hi = hi.cwiseMax(X);
    }
    return piece.nodeX.empty() ? 0.0 : (hi - lo).maxCoeff();
}

// Nodes this close to x = 0, relative to the section's size, lie on the axis: the mesh's
// coordinates carry round-off.
constexpr double kOnAxis = 1e-9;

}  // namespace

void requireRevolvableSection(const HexSolid& solid, int sectors, const std::string& source) {
    if (solid.dimension() != 2)
        throw InputError(source +
                         ": a 3-D particle file; --revolve sweeps a 2-D (axisymmetric) section");
    for (const SolidPiece& piece : solid.pieces()) {
        // The revolved piece's connectivity (8 ids per cell and sector) is counted in Index.
        const double ids = 8.0 * static_cast<double>(piece.cells()) * sectors;
        if (ids > static_cast<double>(std::numeric_limits<Index>::max()))
            throw InputError(source + ": space " + std::to_string(piece.space) + "'s " +
                             std::to_string(piece.cells()) + " cells in " +
                             std::to_string(sectors) +
                             " sectors are too many for one revolved piece; use fewer sectors");
        const double tolerance = kOnAxis * sectionSize(piece);
        for (const Vec3& X : piece.nodeX)
            if (X[0] < -tolerance)
                throw InputError(source + ": a node of space " + std::to_string(piece.space) +
                                 " lies at " + point(X) +
                                 ", at x < 0; --revolve needs a section at x = r ≥ 0");
    }
}

namespace {

// Per node of a piece: does it lie on the axis x = 0 (in the reference configuration)?
std::vector<bool> nodesOnAxis(const SolidPiece& piece) {
    const double tolerance = kOnAxis * sectionSize(piece);
    std::vector<bool> onAxis(piece.nodeX.size());
    for (std::size_t i = 0; i < onAxis.size(); ++i)
        onAxis[i] = std::abs(piece.nodeX[i][0]) <= tolerance;
    return onAxis;
}

}  // namespace

double solidOfRevolutionVolume(const SolidPiece& piece, const std::vector<Vec3>& nodes) {
    const std::vector<bool> onAxis = nodesOnAxis(piece);
    double moment = 0.0;  // ∫ r dA = Σ over the edges of (r_i + r_j)(r_i y_j − r_j y_i) / 6
    for (const auto& quad : piece.quads)
        for (int c = 0; c < 4; ++c) {
            const auto i = static_cast<std::size_t>(quad[c]);
            const auto j = static_cast<std::size_t>(quad[(c + 1) % 4]);
            const double ri = onAxis[i] ? 0.0 : nodes[i][0], rj = onAxis[j] ? 0.0 : nodes[j][0];
            moment += (ri + rj) * (ri * nodes[j][1] - rj * nodes[i][1]) / 6.0;
        }
    return 2.0 * std::numbers::pi * moment;
}

RevolvedCells revolveSection(const SolidPiece& piece, const std::vector<Vec3>& nodes, int sectors) {
    RevolvedCells out;
    const double step = 2.0 * std::numbers::pi / sectors;
    // Node ids: a node on the axis once, every other node once per angle 2π k/N.
    std::vector<Index> first(nodes.size());
    const std::vector<bool> onAxis = nodesOnAxis(piece);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        first[i] = static_cast<Index>(out.nodes.size());
        const int copies = onAxis[i] ? 1 : sectors;
        for (int k = 0; k < copies; ++k) {
            const double phi = k * step, c = std::cos(phi), s = std::sin(phi);
            const double r = onAxis[i] ? 0.0 : nodes[i][0], R = onAxis[i] ? 0.0 : piece.nodeX[i][0];
            out.nodes.emplace_back(r * c, nodes[i][1], r * s);
            out.nodeX.emplace_back(R * c, piece.nodeX[i][1], R * s);
        }
    }
    auto id = [&](Index node, int k) {
        const auto i = static_cast<std::size_t>(node);
        return onAxis[i] ? first[i] : first[i] + k % sectors;
    };
    for (int sector = 0; sector < sectors; ++sector) {
        for (std::size_t q = 0; q < piece.quads.size(); ++q) {
            const std::array<Index, 4>& quad = piece.quads[q];
            std::array<Index, 8> hex;
            for (int c = 0; c < 4; ++c) {
                hex[c] = id(quad[c], sector);
                hex[c + 4] = id(quad[c], sector + 1);
            }
            // The corners on the axis; two adjacent ones (an edge i → j on it) make a wedge.
            int axisCorners = 0, edge = -1;
            for (int c = 0; c < 4; ++c) {
                const auto n = static_cast<std::size_t>(quad[c]);
                const auto next = static_cast<std::size_t>(quad[(c + 1) % 4]);
                axisCorners += onAxis[n];
                if (onAxis[n] && onAxis[next]) edge = c;
            }
            out.offsets.push_back(static_cast<Index>(out.connectivity.size()));
            if (axisCorners == 2 && edge >= 0) {
                // Triangles swept by the edges j → k and i → l (the quadrilateral runs i, j, k,
                // l counter-clockwise): the first's normal points away from the second, as
                // VTK_WEDGE wants, because the quadrilateral turns counter-clockwise.
                const int i = edge, j = (edge + 1) % 4, k = (edge + 2) % 4, l = (edge + 3) % 4;
                for (const Index node : {hex[j], hex[k], hex[k + 4], hex[i], hex[l], hex[l + 4]})
                    out.connectivity.push_back(node);
                out.type.push_back(RevolvedCells::kWedge);
            } else {
                for (const Index node : hex) out.connectivity.push_back(node);
                out.type.push_back(RevolvedCells::kHexahedron);
            }
            out.hexes.push_back(hex);
            out.particle.push_back(piece.particle[q]);
            out.angle.push_back((sector + 0.5) * step);
        }
    }
    out.offsets.push_back(static_cast<Index>(out.connectivity.size()));
    return out;
}

double RevolvedCells::volume() const {
    // A wedge is the hexahedron with its axis edge collapsed: the same faces, the same volume.
    double total = 0.0;
    for (const auto& hex : hexes) {
        std::array<Vec3, 8> x;
        for (int c = 0; c < 8; ++c) x[c] = nodes[static_cast<std::size_t>(hex[c])];
        total += hexahedronVolume(x);
    }
    return total;
}

ParticleFileLocation locateParticleFile(const std::filesystem::path& runDir,
                                        const std::filesystem::path& given) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!given.empty()) {
        if (fs::is_regular_file(given, ec)) return {given, "given with --particles"};
        return {std::nullopt, given.string() + ": no such particle file"};
    }
    const fs::path checkpoint = runDir / "checkpoint.h5";
    std::string recorded;
    if (fs::is_regular_file(checkpoint, ec)) {
        try {
            const std::string bytes = runInChild(
                checkpoint.string(), "the checkpoint reader",
                [&](ByteWriter& w) {
                    const h5::File h5(checkpoint, h5::File::Mode::ReadOnly);
                    const std::vector<std::string> roles = h5.readStrings("/run/inputs/role");
                    const std::vector<std::string> files = h5.readStrings("/run/inputs/file");
                    for (std::size_t i = 0; i < roles.size() && i < files.size(); ++i)
                        if (roles[i] == "particles") w.text(files[i]);
                },
                [&](const std::string& reason) {
                    throw IoError(checkpoint.string() + ": crashed HDF5's reader (" + reason + ")");
                },
                fileReadDeadline(checkpoint));
            if (!bytes.empty()) recorded = ByteReader(bytes, checkpoint.string()).text();
        } catch (const std::exception&) {  // an unreadable checkpoint: try the next place
        }
    }
    if (!recorded.empty()) {
        const fs::path named(recorded);
        if (fs::is_regular_file(named, ec)) return {named, "named by " + checkpoint.string()};
        if (fs::is_regular_file(runDir / named.filename(), ec))
            return {runDir / named.filename(), "named by " + checkpoint.string()};
    }
    if (fs::is_regular_file(runDir / "particles.h5", ec))
        return {runDir / "particles.h5", "found in the run folder"};
    return {std::nullopt,
            recorded.empty()
                ? "no particle file found (no checkpoint.h5 naming it, no particles.h5 in " +
                      runDir.string() + "); pass --particles FILE"
                : "the run's particle file " + recorded +
                      " (named by its checkpoint.h5) is gone; pass --particles FILE"};
}

}  // namespace gsph::post
