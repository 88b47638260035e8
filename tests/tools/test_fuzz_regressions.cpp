// SPDX-License-Identifier: MIT
// The inputs the fuzz targets (tests/fuzz, docs/testing.md) found faults with, kept in
// tests/data/fuzz_regressions/<target>/, and the targets' seed corpus (tests/fuzz/corpus/<target>/:
// valid files and crafted bad ones): each goes through the very calls of its target
// (tests/fuzz/entry_points.hpp), under the same file name, and must succeed or throw a typed
// gsph::Error — never crash or throw anything else.
#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz/child_fault.hpp"
#include "fuzz/entry_points.hpp"
#include "io/snapshot.hpp"
#include "temp_dir.hpp"

namespace gsph {
namespace {

const std::filesystem::path kRegressions =
    std::filesystem::path(GSPH_SOURCE_DIR) / "tests/data/fuzz_regressions";
const std::filesystem::path kCorpus = std::filesystem::path(GSPH_SOURCE_DIR) / "tests/fuzz/corpus";

/// The regression files of `target`, then its seed corpus.
std::vector<std::filesystem::path> inputFiles(const std::string& target) {
    std::vector<std::filesystem::path> files;
    for (const std::filesystem::path& root : {kRegressions, kCorpus}) {
        const std::filesystem::path dir = root / target;
        if (!std::filesystem::exists(dir)) continue;
        const std::size_t first = files.size();
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (entry.is_regular_file()) files.push_back(entry.path());
        }
        std::sort(files.begin() + static_cast<std::ptrdiff_t>(first), files.end());
    }
    return files;
}

/// Success, or a gsph::Error; the message of an error, empty on success.
::testing::AssertionResult typedOutcome(const std::function<void()>& read, std::string& message) {
    try {
        read();
        message.clear();
        return ::testing::AssertionSuccess();
    } catch (const Error& e) {
        message = e.what();
        return ::testing::AssertionSuccess();
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "untyped exception: " << e.what();
    }
}

/// Runs every input file of `target` through `read`, copied under `name` into a scratch folder
/// as the fuzz target writes its input; returns the number of files.
std::size_t runAll(const std::string& target, const std::string& name,
                   const std::function<void(const std::filesystem::path&)>& read) {
    const std::vector<std::filesystem::path> files = inputFiles(target);
    for (const std::filesystem::path& file : files) {
        test::TempDir dir;
        std::filesystem::copy_file(file, dir / name);
        std::string message;
        EXPECT_TRUE(typedOutcome([&] { read(dir / name); }, message)) << file;
    }
    return files.size();
}

TEST(FuzzRegressions, CaseFilesGiveATypedErrorOrSucceed) {
    EXPECT_GT(runAll("case", "case.toml", fuzz::readCase), 0u);
}

TEST(FuzzRegressions, MaterialFilesGiveATypedErrorOrSucceed) {
    EXPECT_GT(runAll("material", "fuzz_material.toml", fuzz::readMaterial), 0u);
}

// Both forms of the particle-file and .msh readers: in process (our code around the parser, under
// this build's sanitizers) and as the tools call them (the parser in a child process).
TEST(FuzzRegressions, ParticleFilesGiveATypedErrorOrSucceed) {
    EXPECT_GT(runAll("particle_file", "particles.h5", fuzz::readParticlesInProcess), 0u);
    EXPECT_GT(runAll("particle_file", "particles.h5", fuzz::readParticles), 0u);
}

TEST(FuzzRegressions, MeshFilesGiveATypedErrorOrSucceed) {
    EXPECT_GT(runAll("msh", "fuzz.msh", fuzz::readMeshInProcess), 0u);
    EXPECT_GT(runAll("msh", "fuzz.msh", fuzz::readMesh), 0u);
}

// A particle-file regression is refused by both forms of the reader with an IoError naming the
// file and `dataset`.
void expectRefusedNaming(const char* name, const char* dataset) {
    const std::filesystem::path file = kRegressions / "particle_file" / name;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    for (const auto read : {fuzz::readParticlesInProcess, fuzz::readParticles}) {
        try {
            read(file);
            ADD_FAILURE() << file << " was accepted";
        } catch (const IoError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(file.string()), std::string::npos) << message;
            EXPECT_NE(message.find(dataset), std::string::npos) << message;
        }
    }
}

// /spaces/cells that disagree with the file's particles: 32-bit products of these overflowed in
// the cell list (SIGSEGV), or sized it at 8 GB. The reader refuses them, naming the file and
// the dataset.
TEST(FuzzRegressions, SpaceCellsThatDisagreeWithTheParticlesAreRefused) {
    const char* files[] = {"cells_1073741824x4x4.h5", "cells_2147483647x2147483647x2147483647.h5",
                           "cells_1048576x1x1_without_lattice_index.h5"};
    for (const char* name : files) expectRefusedNaming(name, "/spaces/cells");
}

// A flipped byte made /spaces/dtheta claim 263882790666241 elements in a 16 kB file: the reader
// allocated them (2 PB) before reading. Refused from the bytes the file stores, naming the
// dataset.
TEST(FuzzRegressions, DataspaceLargerThanItsStorageIsRefused) {
    expectRefusedNaming("corrupt_dataspace_spaces_dtheta.h5", "/spaces/dtheta");
}

// The fuzzers' file on which HDF5 1.10.8 never returns (tests/fuzz/third_party_findings), read
// as a snapshot in a child process with a deadline of 2 s: an IoError naming the file and the
// alarm, and the caller goes on.
TEST(ThirdPartyFindings, ASnapshotThatHangsHdf5IsStoppedByTheDeadline) {
    const std::filesystem::path hang =
        std::filesystem::path(GSPH_SOURCE_DIR) /
        "tests/fuzz/third_party_findings/hdf5_H5C_protect_timeout.h5";
    try {
        (void)readSnapshotIsolated(hang, 2);
        FAIL() << "read";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), hang.string() +
                                             ": the file crashed or hung HDF5's reader (signal "
                                             "14, Alarm clock): it is damaged or not a snapshot");
    }
}

// A sanitizer report in a reader's child process of a fuzz target (tests/fuzz/child_fault.hpp):
// a fault inside HDF5 or gmsh is contained (their module), any other is a finding ("").
const std::string kExe = "/w/build-fuzz/tests/fuzz/fuzz_particle_file";

std::string report(const std::string& firstStack) {
    return "==7==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x6020 at pc 0x55\n"
           "READ of size 16 at 0x6020 thread T0\n" +
           firstStack +
           "\n0x6020 is located 0 bytes to the right of 1-byte region\n"
           "allocated by thread T0 here:\n"
           "    #0 0x55 in malloc (" +
           kExe +
           "+0x4a2000) (BuildId: ab)\n"
           "    #1 0x7f in H5FL_blk_malloc (/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1f0)\n"
           "\nSUMMARY: AddressSanitizer: heap-buffer-overflow in __asan_memcpy\n";
}

TEST(ChildFaults, AFaultInsideHdf5OrGmshIsTheirs) {
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x55 in __asan_memcpy (" + kExe +
                         "+0x4a1b2c) (BuildId: ab)\n"
                         "    #1 0x7f in H5O__msg_iterate_real "
                         "(/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1a2b3c) (BuildId: cd)\n"
                         "    #2 0x55 in gsph::h5::File::hasAttribute() const "
                         "/w/libgsph/io/hdf5_file.cpp:210:12\n"),
                  kExe),
              "libhdf5_serial.so.103");
    EXPECT_EQ(
        fuzz::thirdPartyFaultModule(report("    #0 0x55 in operator new(unsigned long) (" + kExe +
                                           "+0x4a3000)\n"
                                           "    #1 0x7f in std::__throw_bad_alloc() "
                                           "(/lib/x86_64-linux-gnu/libstdc++.so.6+0xa1b2c)\n"
                                           "    #2 0x7f in GModel::_readMSH2(std::string const&) "
                                           "(/lib/x86_64-linux-gnu/libgmsh.so.4.8+0x1234)\n"),
                                    kExe),
        "libgmsh.so.4.8");
    // A static function of HDF5's has no name, only its module.
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x55 in memcpy (" + kExe +
                         "+0xc35d3) (BuildId: 58)\n"
                         "    #1 0x7f  (/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x190f18) "
                         "(BuildId: e9)\n"
                         "    #2 0x7f in H5O__msg_iterate_real "
                         "(/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1b4ca4)\n"),
                  kExe),
              "libhdf5_serial.so.103");
}

TEST(ChildFaults, AFaultInOurCodeOrOneThatCannotBeToldIsAFinding) {
    // Our frame (a source line) first, under the runtime's.
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x55 in __asan_memcpy (" + kExe +
                         "+0x4a1b2c)\n"
                         "    #1 0x55 in gsph::readParticleFile(std::filesystem::path const&) "
                         "/w/libgsph/io/particle_file.cpp:310:5\n"
                         "    #2 0x7f in H5Literate2 "
                         "(/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1a2b3c)\n"),
                  kExe),
              "");
    // Not symbolized: our code and the runtime look alike.
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x55  (" + kExe +
                         "+0x4a1b2c)\n"
                         "    #1 0x7f  (/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1a2b3c)\n"),
                  kExe),
              "");
    // Another library's frame; a first stack of the runtime alone (the allocation's stack, in
    // HDF5, is not the fault's).
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x7f in inflate (/lib/x86_64-linux-gnu/libz.so.1+0x9f00)\n"
                         "    #1 0x7f in H5Z__filter_deflate "
                         "(/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x2b3c)\n"),
                  kExe),
              "");
    EXPECT_EQ(fuzz::thirdPartyFaultModule(
                  report("    #0 0x55 in __asan_memcpy (" + kExe + "+0x4a1b2c)\n"), kExe),
              "");
    EXPECT_EQ(fuzz::thirdPartyFaultModule("", kExe), "");
}

}  // namespace
}  // namespace gsph
