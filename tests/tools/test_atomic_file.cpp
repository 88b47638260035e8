// SPDX-License-Identifier: MIT
// Atomic output: complete file after commit, nothing left behind on failure.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "temp_dir.hpp"

namespace gsph {
namespace {

std::string contents(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(AtomicFile, CommitRenamesOntoTarget) {
    test::TempDir dir;
    const auto target = dir / "out.txt";
    writeAtomically(target, [&](const std::filesystem::path& temp) {
        EXPECT_EQ(temp.parent_path(), dir.path());
        EXPECT_FALSE(std::filesystem::exists(target));
        std::ofstream(temp) << "new";
    });
    EXPECT_EQ(contents(target), "new");
    EXPECT_EQ(dir.entries(), 1);
}

TEST(AtomicFile, TempFileLivesNextToTarget) {
    test::TempDir dir;
    AtomicFile file(dir / "out.h5");
    EXPECT_EQ(file.tempPath().parent_path(), dir.path());
    EXPECT_NE(file.tempPath(), file.target());
}

TEST(AtomicFile, FailureLeavesNothingAndKeepsOldTarget) {
    test::TempDir dir;
    const auto target = dir / "out.txt";
    std::ofstream(target) << "old";
    EXPECT_THROW(writeAtomically(target,
                                 [](const std::filesystem::path& temp) {
                                     std::ofstream(temp) << "half";
                                     throw std::runtime_error("disk full");
                                 }),
                 std::runtime_error);
    EXPECT_EQ(contents(target), "old");
    EXPECT_EQ(dir.entries(), 1);
}

TEST(AtomicFile, MissingFolderIsAnIoError) {
    test::TempDir dir;
    EXPECT_THROW(AtomicFile(dir / "no-such-folder" / "out.h5"), IoError);
    EXPECT_THROW(AtomicFile(dir.path()), IoError);
}

TEST(AtomicFile, CommitWithoutWritingIsAnIoError) {
    test::TempDir dir;
    AtomicFile file(dir / "out.h5");
    EXPECT_THROW(file.commit(), IoError);
    EXPECT_EQ(dir.entries(), 0);
}

}  // namespace
}  // namespace gsph
