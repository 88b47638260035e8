// SPDX-License-Identifier: MIT
// libFuzzer target: bytes → a particle file → the reader as gsph-solve calls it
// (readParticleFileIsolated: HDF5's parser in a child process), validateParticleFile and
// buildReference (docs/testing.md): any crash, hang or sanitizer report is a finding.
// GSPH_FUZZ_IN_PROCESS=1 calls readParticleFile in this process instead (HDF5's parser and our
// reader under coverage; a crash inside HDF5 is HDF5's).
//
// Raw bytes rarely get past HDF5's open, so the input is read two ways:
//   * it starts with the HDF5 signature: the bytes are the file (raw mode; the seed corpus holds
//     small valid particle files);
//   * otherwise (structure-aware): FuzzedDataProvider picks one of three valid seed files, turns
//     it into its datasets and attributes, mutates them (lengths, shapes, element types, counts,
//     /spaces/cells up to 2^31−1, indices out of range, NaN, negative volumes, missing datasets,
//     /set_areas of wrong lengths or of sets that do not exist)
//     and writes them with the project's h5 layer, so that sizes can disagree; then it may flip
//     a few bytes of the written file.
// GSPH_FUZZ_SAVE=FILE keeps a copy of the last particle file written (to turn a finding into a
// regression file of tests/data/fuzz_regressions/particle_file/). GSPH_FUZZ_STRUCTURED_ONLY=1
// leaves out the raw mode and the flipped bytes, whose findings are mostly HDF5's own.
#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "entry_points.hpp"
#include "fuzz_support.hpp"
#include "io/hdf5_file.hpp"
#include "io/particle_file.hpp"
#include "reference/reference_builder.hpp"

namespace {

using gsph::Index;
using gsph::ParticleFile;
using gsph::Vec3;

/// One body of a 2×2×1 space and one of a periodic 3×1×1 space (tests/tools/test_particle_file).
ParticleFile twoBodies() {
    ParticleFile f;
    f.spaces.resize(2);
    f.spaces[0].cells = {2, 2, 1};
    f.spaces[1].cells = {3, 1, 1};
    f.spaces[1].periodic = {true, false, false};
    auto add = [&](Index s, Index b, std::array<Index, 3> ijk) {
        const Vec3 theta(ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5);
        f.theta.push_back(theta);
        f.X.push_back(1e-3 * theta + Vec3(0.1 * b, 0.0, 0.0));
        f.volume.push_back(1e-9);
        f.space.push_back(s);
        f.body.push_back(b);
        f.latticeIndex.push_back(ijk);
    };
    for (Index j = 0; j < 2; ++j)
        for (Index i = 0; i < 2; ++i) add(0, 0, {i, j, 0});
    for (Index i = 0; i < 3; ++i) add(1, 1, {i, 0, 0});
    f.bodies = {{"plate", 1}, {"projectile", 2}};
    f.sets["clamp"] = {0, 2};
    f.sets["tip"] = {4, 5, 6};
    f.setAreas["tip"] = {Vec3(1e-6, 0.0, 0.0), Vec3(0.0, 1e-6, 0.0), Vec3(0.0, 0.0, -1e-6)};
    f.provenance = {"gsph-fuzz", "0", "plate.geo", std::string(64, 'a'), "", "SI"};
    return f;
}

/// One body of two overlapping spaces with transient particles (DESIGN §6) and a second body.
ParticleFile overset() {
    ParticleFile f;
    f.spaces.resize(3);
    f.spaces[0].cells = {2, 2, 1};
    f.spaces[1].cells = {3, 1, 1};
    f.spaces[1].dtheta = 0.5;
    f.spaces[2].cells = {2, 1, 1};
    auto add = [&](Index s, Index b, std::array<Index, 3> ijk) {
        const double d = f.spaces[static_cast<std::size_t>(s)].dtheta;
        const Vec3 theta = d * Vec3(ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5);
        f.theta.push_back(theta);
        f.X.push_back(1e-3 * theta + Vec3(0.1 * s, 0.0, 0.0));
        f.volume.push_back(1e-9);
        f.space.push_back(s);
        f.body.push_back(b);
        f.latticeIndex.push_back(ijk);
    };
    for (Index j = 0; j < 2; ++j)
        for (Index i = 0; i < 2; ++i) add(0, 0, {i, j, 0});
    for (Index i = 0; i < 3; ++i) add(1, 0, {i, 0, 0});
    for (Index i = 0; i < 2; ++i) add(2, 1, {i, 0, 0});
    f.bodies = {{"rod", 1}, {"anvil", 2}};
    f.transient = {0, 1, 0, 1, 1, 1, 0, 0, 0};
    f.overset.kappa = 1.5;
    f.overset.particle = {4, 5, 1, 3};
    f.overset.space = {0, 0, 1, 1};
    f.overset.theta = {Vec3(2.25, 0.5, 0.5), Vec3(2.75, 0.5, 0.5), Vec3(-0.25, 0.5, 0.25),
                       Vec3(-0.75, 0.5, 0.25)};
    f.overset.omega = {0.125, 0.125, 8.0, 8.0};
    f.provenance = {"gsph-fuzz", "0", "rod.geo", std::string(64, 'b'), "", "SI"};
    return f;
}

/// One space of up to 4×4×4 cells filled in lattice order, without lattice indices.
ParticleFile block(FuzzedDataProvider& in) {
    ParticleFile f;
    f.spaces.resize(1);
    for (int& n : f.spaces[0].cells) n = in.ConsumeIntegralInRange(1, 4);
    f.spaces[0].periodic[0] = in.ConsumeBool();
    const auto& c = f.spaces[0].cells;
    for (Index k = 0; k < c[2]; ++k)
        for (Index j = 0; j < c[1]; ++j)
            for (Index i = 0; i < c[0]; ++i) {
                f.theta.push_back(Vec3(i + 0.5, j + 0.5, k + 0.5));
                f.X.push_back(1e-3 * f.theta.back());
                f.volume.push_back(1e-9);
                f.space.push_back(0);
                f.body.push_back(0);
            }
    f.bodies = {{"", -1}};
    f.transient.assign(f.X.size(), 0);
    f.overset.kappa = 1.5;
    return f;
}

/// A dataset as the fuzzer edits it: values held as doubles (every int32 is exact), written with
/// the element type `type` and the shape `dims`.
struct Dataset {
    enum class Type { F64, I32, I8, Strings };
    std::string path;
    Type type = Type::F64;
    std::vector<std::size_t> dims;
    std::vector<double> values;
    std::vector<std::string> strings;
};

template <class T>
Dataset column(const std::string& path, Dataset::Type type, const T* data, std::size_t rows,
               std::size_t cols) {
    Dataset d{path,
              type,
              cols == 0 ? std::vector<std::size_t>{rows} : std::vector<std::size_t>{rows, cols},
              {},
              {}};
    const std::size_t count = rows * (cols == 0 ? 1 : cols);
    for (std::size_t i = 0; i < count; ++i) d.values.push_back(static_cast<double>(data[i]));
    return d;
}

std::vector<Dataset> datasetsOf(const ParticleFile& f) {
    using T = Dataset::Type;
    const std::size_t n = f.X.size(), m = f.overset.size(), s = f.spaces.size();
    std::vector<Dataset> out;
    out.push_back(column("/particles/X", T::F64, f.X.empty() ? nullptr : f.X[0].data(), n, 3));
    out.push_back(
        column("/particles/theta", T::F64, f.theta.empty() ? nullptr : f.theta[0].data(), n, 3));
    out.push_back(column("/particles/volume", T::F64, f.volume.data(), n, 0));
    out.push_back(column("/particles/space", T::I32, f.space.data(), n, 0));
    out.push_back(column("/particles/body", T::I32, f.body.data(), n, 0));
    if (!f.latticeIndex.empty())
        out.push_back(column("/particles/lattice_index", T::I32, f.latticeIndex[0].data(), n, 3));
    std::vector<std::int32_t> cells;
    std::vector<std::int8_t> periodic;
    std::vector<double> dtheta;
    for (const gsph::LatticeSpace& sp : f.spaces) {
        for (std::size_t d = 0; d < 3; ++d) {
            cells.push_back(sp.cells[d]);
            periodic.push_back(sp.periodic[d] ? 1 : 0);
        }
        dtheta.push_back(sp.dtheta);
    }
    out.push_back(column("/spaces/cells", T::I32, cells.data(), s, 3));
    out.push_back(column("/spaces/periodic", T::I8, periodic.data(), s, 3));
    out.push_back(column("/spaces/dtheta", T::F64, dtheta.data(), s, 0));
    Dataset names{"/bodies/name", T::Strings, {f.bodies.size()}, {}, {}};
    std::vector<std::int32_t> tags;
    for (const gsph::BodyInfo& b : f.bodies) {
        names.strings.push_back(b.name);
        tags.push_back(b.sourceTag);
    }
    out.push_back(names);
    out.push_back(column("/bodies/source_tag", T::I32, tags.data(), tags.size(), 0));
    for (const auto& [name, members] : f.sets)
        out.push_back(column("/sets/" + name, T::I32, members.data(), members.size(), 0));
    for (const auto& [name, areas] : f.setAreas)
        out.push_back(column("/set_areas/" + name, T::F64,
                             areas.empty() ? nullptr : areas[0].data(), areas.size(), 3));
    if (!f.transient.empty()) {
        const auto& o = f.overset;
        out.push_back(column("/particles/transient", T::I8, f.transient.data(), n, 0));
        out.push_back(column("/overset/particle", T::I32, o.particle.data(), m, 0));
        out.push_back(column("/overset/space", T::I32, o.space.data(), m, 0));
        out.push_back(
            column("/overset/theta", T::F64, o.theta.empty() ? nullptr : o.theta[0].data(), m, 3));
        out.push_back(column("/overset/omega", T::F64, o.omega.data(), m, 0));
        out.push_back(column("/overset/kappa", T::F64, &o.kappa, 1, 0));
    }
    return out;
}

std::size_t elementCount(const std::vector<std::size_t>& dims) {
    std::size_t count = 1;
    for (std::size_t d : dims) count *= d;
    return count;
}

constexpr double kTwo30 = 1073741824.0;
constexpr double kInt32Max = 2147483647.0;

double specialValue(FuzzedDataProvider& in, const Dataset& d) {
    const double rows = d.dims.empty() ? 0.0 : static_cast<double>(d.dims[0]);
    if (d.type == Dataset::Type::F64) {
        const double pick[] = {std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               -1.0,
                               0.0,
                               -0.0,
                               1e-310,
                               1e308,
                               -1e308,
                               0.5,
                               2.0,
                               kTwo30,
                               in.ConsumeFloatingPoint<double>()};
        return pick[in.ConsumeIntegralInRange<std::size_t>(0, std::size(pick) - 1)];
    }
    const double pick[] = {0.0,
                           -1.0,
                           1.0,
                           2.0,
                           rows,
                           rows - 1.0,
                           rows + 1.0,
                           kTwo30,
                           kInt32Max,
                           -kInt32Max - 1.0,
                           127.0,
                           -128.0,
                           static_cast<double>(in.ConsumeIntegral<std::int32_t>())};
    return pick[in.ConsumeIntegralInRange<std::size_t>(0, std::size(pick) - 1)];
}

/// One edit of one dataset (or of the list: drop or add one).
void mutate(FuzzedDataProvider& in, std::vector<Dataset>& data) {
    if (data.empty()) return;
    Dataset& d = data[in.ConsumeIntegralInRange<std::size_t>(0, data.size() - 1)];
    const std::size_t count = elementCount(d.dims);
    switch (in.ConsumeIntegralInRange(0, 8)) {
        case 0:  // one element to a special value
        case 1:
            if (count > 0 && d.type != Dataset::Type::Strings)
                d.values[in.ConsumeIntegralInRange<std::size_t>(0, count - 1)] =
                    specialValue(in, d);
            break;
        case 2:  // one element off by one
            if (count > 0 && d.type != Dataset::Type::Strings)
                d.values[in.ConsumeIntegralInRange<std::size_t>(0, count - 1)] +=
                    in.ConsumeBool() ? 1.0 : -1.0;
            break;
        case 3: {  // another number of rows
            const std::size_t rows = d.dims.empty() ? 0 : d.dims[0];
            const std::size_t pick[] = {0, rows > 0 ? rows - 1 : 0, rows + 1,
                                        in.ConsumeIntegralInRange<std::size_t>(0, 40)};
            if (d.dims.empty()) d.dims.push_back(0);
            d.dims[0] = pick[in.ConsumeIntegralInRange<std::size_t>(0, 3)];
            break;
        }
        case 4: {  // another shape: 1-D, or N×1 … N×4
            const std::size_t cols = in.ConsumeIntegralInRange<std::size_t>(0, 4);
            const std::size_t rows = d.dims.empty() ? 0 : d.dims[0];
            d.dims =
                cols == 0 ? std::vector<std::size_t>{rows} : std::vector<std::size_t>{rows, cols};
            break;
        }
        case 5:  // another element type
            if (d.type != Dataset::Type::Strings)
                d.type = static_cast<Dataset::Type>(in.ConsumeIntegralInRange(0, 2));
            break;
        case 6:  // a space's cells, the whole row (the products of theta_search.cpp)
            if (d.path == "/spaces/cells" && count >= 3) {
                const std::array<double, 3> rows[] = {
                    {kTwo30, 4, 4},    {kInt32Max, kInt32Max, kInt32Max},
                    {kInt32Max, 1, 1}, {65536, 65536, 1},
                    {0, 4, 4},         {-4, 4, 4}};
                const auto& row = rows[in.ConsumeIntegralInRange<std::size_t>(0, 5)];
                const std::size_t s = 3 * in.ConsumeIntegralInRange<std::size_t>(0, count / 3 - 1);
                for (std::size_t k = 0; k < 3; ++k) d.values[s + k] = row[k];
            } else if (d.type == Dataset::Type::Strings && !d.strings.empty()) {
                d.strings[0] = in.ConsumeRandomLengthString(16);
            }
            break;
        case 7:  // drop it
            data.erase(data.begin() + (&d - data.data()));
            return;
        default: {  // a set with an odd name or odd members, or face areas of a set that may not
                    // exist (clamp is one of twoBodies(), none never is)
            const char* names[] = {"/sets/.",   "/sets/x y",        "/sets/big",
                                   "/sets/neg", "/set_areas/clamp", "/set_areas/none"};
            const std::size_t pick = in.ConsumeIntegralInRange<std::size_t>(0, 5);
            Dataset set{names[pick], Dataset::Type::I32, {2}, {}, {}};
            if (pick >= 4) {
                set.type = Dataset::Type::F64;
                set.dims = {2, 3};
                set.values.assign(6, 1e-6);
                set.values[in.ConsumeIntegralInRange<std::size_t>(0, 5)] = specialValue(in, set);
            } else {
                set.values = {specialValue(in, set), specialValue(in, set)};
            }
            data.push_back(set);
            return;
        }
    }
    if (d.type == Dataset::Type::Strings) {
        d.strings.resize(d.dims.empty() ? 0 : d.dims[0]);
        d.dims = {d.strings.size()};
    } else {
        d.values.resize(elementCount(d.dims), d.values.empty() ? 1.0 : d.values.back());
    }
}

/// A double as an int32 the way a careless converter would not: NaN → 0, others wrap modulo 2^32
/// (C++20 conversion), so every bit pattern is reachable without undefined behaviour.
template <class T>
std::vector<T> asIntegers(const std::vector<double>& values) {
    std::vector<T> out;
    for (double v : values) {
        const double c = std::isfinite(v) ? std::fmax(-9.2e18, std::fmin(9.2e18, v)) : 0.0;
        out.push_back(static_cast<T>(static_cast<std::int64_t>(c)));
    }
    return out;
}

void write(const std::filesystem::path& path, const std::vector<Dataset>& data,
           const gsph::Provenance& provenance, FuzzedDataProvider& in) {
    gsph::h5::File h5(path, gsph::h5::File::Mode::Create);
    // Each choice is 0 (keep the seed's) for an empty input: the empty input is the valid seed.
    const char* versions[] = {"1.1", "1.0", "2.0", "1", "", ".", "1.1.1"};
    const bool otherFormat = in.ConsumeIntegralInRange(0, 15) == 15;
    h5.setAttribute("/", "format",
                    std::string(otherFormat ? "gsph-snapshot" : gsph::kParticleFormat));
    const bool otherVersion = in.ConsumeIntegralInRange(0, 15) == 15;
    h5.setAttribute("/", "format_version",
                    std::string(versions[otherVersion ? in.ConsumeIntegralInRange(1, 6) : 0]));
    if (in.ConsumeIntegralInRange(0, 15) != 15) gsph::writeProvenance(h5, provenance);
    for (const Dataset& d : data) {
        switch (d.type) {
            case Dataset::Type::F64:
                h5.write(d.path, d.values.data(), d.dims);
                break;
            case Dataset::Type::I32:
                h5.write(d.path, asIntegers<std::int32_t>(d.values).data(), d.dims);
                break;
            case Dataset::Type::I8:
                h5.write(d.path, asIntegers<std::int8_t>(d.values).data(), d.dims);
                break;
            case Dataset::Type::Strings:
                h5.writeStrings(d.path, d.strings);
                break;
        }
    }
    h5.close();  // a created file reaches the disk only here
}

/// Flips up to four bytes of the written file (the HDF5 structures themselves).
void corrupt(const std::filesystem::path& path, FuzzedDataProvider& in) {
    std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
    const auto size = static_cast<std::size_t>(std::filesystem::file_size(path));
    const int flips = in.ConsumeIntegralInRange(1, 4);
    for (int k = 0; k < flips && size > 0; ++k) {
        const std::size_t at = in.ConsumeIntegralInRange<std::size_t>(0, size - 1);
        char c = 0;
        file.seekg(static_cast<std::streamoff>(at));
        file.read(&c, 1);
        c = static_cast<char>(c ^ static_cast<char>(in.ConsumeIntegralInRange(1, 255)));
        file.seekp(static_cast<std::streamoff>(at));
        file.write(&c, 1);
    }
}

/// The particle file of a structure-aware input; false if the h5 layer refused to write it.
bool structured(const std::uint8_t* data, std::size_t size, const std::filesystem::path& path,
                bool mayCorrupt) {
    FuzzedDataProvider in(data, size);
    const int seed = in.ConsumeIntegralInRange(0, 2);
    const ParticleFile f = seed == 0 ? twoBodies() : seed == 1 ? overset() : block(in);
    std::vector<Dataset> datasets = datasetsOf(f);
    const int edits = in.ConsumeIntegralInRange(0, 6);
    for (int k = 0; k < edits; ++k) mutate(in, datasets);
    try {
        write(path, datasets, f.provenance, in);
    } catch (const gsph::IoError&) {
        return false;  // e.g. a dataset whose parent is a dataset: not a particle file's fault
    }
    if (in.ConsumeIntegralInRange(0, 7) == 7 && mayCorrupt) corrupt(path, in);
    return true;
}

constexpr unsigned char kHdf5Signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool structuredOnly = std::getenv("GSPH_FUZZ_STRUCTURED_ONLY") != nullptr;
    gsph::fuzz::currentData = data;
    gsph::fuzz::currentSize = size;
    std::filesystem::path path = gsph::fuzz::scratchDir() / "particles.h5";
    if (!structuredOnly && size >= sizeof kHdf5Signature &&
        std::memcmp(data, kHdf5Signature, 8) == 0) {
        path = gsph::fuzz::writeScratch("particles.h5", data, size);
    } else if (!structured(data, size, path, !structuredOnly)) {
        return 0;
    }
    if (const char* keep = std::getenv("GSPH_FUZZ_SAVE")) {
        std::filesystem::copy_file(path, keep, std::filesystem::copy_options::overwrite_existing);
    }
    gsph::fuzz::expectTypedOutcome([&] {
        gsph::fuzz::parsersInProcess() ? gsph::fuzz::readParticlesInProcess(path)
                                       : gsph::fuzz::readParticles(path);
    });
    return 0;
}
