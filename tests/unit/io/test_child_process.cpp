// SPDX-License-Identifier: MIT
// runInChild (io/child_process.hpp): the child's bytes, its typed errors, and its crashes and
// hangs as errors of the parent, whatever signal handlers the parent has installed.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/child_process.hpp"

namespace gsph {
namespace {

TEST(ChildProcess, ReturnsTheBytesTheChildWrote) {
    const std::string bytes = runInChild("src", "work", [](ByteWriter& w) {
        w.value<std::int32_t>(-7);
        w.text("plate");
        w.array(std::vector<Vec3>{Vec3(1, 2, 3), Vec3(-4, 5e-300, 6)});
    });
    ByteReader r(bytes, "src");
    EXPECT_EQ(r.value<std::int32_t>(), -7);
    EXPECT_EQ(r.text(), "plate");
    const std::vector<Vec3> v = r.array<Vec3>();
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[1], Vec3(-4, 5e-300, 6));
    EXPECT_THROW(r.value<char>(), Error);  // nothing more: a truncated answer
}

TEST(ChildProcess, TheChildsTypedErrorKeepsItsTypeAndMessage) {
    try {
        runInChild("src", "work",
                   [](ByteWriter&) { throw MeshError("m.msh: element 3 inverted"); });
        FAIL() << "no error";
    } catch (const MeshError& e) {
        EXPECT_STREQ(e.what(), "m.msh: element 3 inverted");
    }
    EXPECT_THROW(runInChild("src", "work", [](ByteWriter&) { throw IoError("x"); }), IoError);
}

// A handler of the parent's (a crash reporter, a sanitizer's) is not the child's: it dies by
// the signal, which the parent names.
void ignoreSignal(int) {}

TEST(ChildProcess, ACrashIsTheCallersErrorNamingTheSignal) {
    struct sigaction action = {}, previous = {};
    action.sa_handler = ignoreSignal;
    ::sigaction(SIGSEGV, &action, &previous);
    std::string reason;
    EXPECT_THROW(runInChild(
                     "src", "work", [](ByteWriter&) { ::raise(SIGSEGV); },
                     [&](const std::string& r) {
                         reason = r;
                         throw IoError("src: crashed");
                     }),
                 IoError);
    ::sigaction(SIGSEGV, &previous, nullptr);
    EXPECT_EQ(reason.rfind("signal 11", 0), 0u) << reason;
}

TEST(ChildProcess, AHangIsStoppedByTheDeadline) {
    struct sigaction action = {}, previous = {};
    action.sa_handler = ignoreSignal;
    ::sigaction(SIGALRM, &action, &previous);
    try {
        runInChild(
            "src", "the reader",
            [](ByteWriter&) {
                for (;;) ::pause();
            },
            {}, 1);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "src: the reader crashed (signal 14, Alarm clock)");
    }
    ::sigaction(SIGALRM, &previous, nullptr);
}

}  // namespace
}  // namespace gsph
