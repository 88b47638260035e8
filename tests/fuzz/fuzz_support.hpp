// SPDX-License-Identifier: MIT
// What every fuzz target shares: a scratch folder of its own process, the verdict on an input,
// and the verdict on a sanitizer report in a reader's child process. A gsph::Error is the
// expected answer to bad input; any other exception is reported and aborts, so that libFuzzer
// keeps the input as a crash (the library promises typed errors).
#pragma once

#include <fcntl.h>
#include <sanitizer/asan_interface.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

#include "child_fault.hpp"
#include "core/error.hpp"

namespace gsph::fuzz {

/// A folder of this process under the temporary directory (libFuzzer's -fork and -jobs run
/// several processes), created on first use and removed at exit.
inline const std::filesystem::path& scratchDir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path d =
            std::filesystem::temp_directory_path() / ("gsph-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                            ("gsph-fuzz-" + std::to_string(::getpid())),
                                        ec);
        });
        return d;
    }();
    return dir;
}

/// GSPH_FUZZ_IN_PROCESS=1: the particle-file and .msh targets call HDF5's and gmsh's parsers in
/// this process (under coverage; run with -fork, a crash inside a parser is theirs) instead of
/// in a child process as the tools do (entry_points.hpp).
inline bool parsersInProcess() {
    static const bool inProcess = std::getenv("GSPH_FUZZ_IN_PROCESS") != nullptr;
    return inProcess;
}

/// Writes `size` bytes to `name` in the scratch folder; returns its path.
inline std::filesystem::path writeScratch(const std::string& name, const std::uint8_t* data,
                                          std::size_t size) {
    const std::filesystem::path path = scratchDir() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// The input being run, for a reader's child that has to keep it (ChildFaults).
inline const std::uint8_t* currentData = nullptr;
inline std::size_t currentSize = 0;

/// A sanitizer report in a reader's child process (io/child_process.hpp: runInChild forks the
/// fuzzer, which HDF5's and gmsh's parsers then run in). The child inherits libFuzzer's death
/// callback, which would keep the input as a crash-* artifact while the fuzzer itself survives
/// (the child's end is a typed error, as in the tools) — also for a fault inside HDF5 or gmsh,
/// and for one that depends on the state the child inherited (the fuzzer's heap), which need not
/// recur when the input is run alone. So the child judges its report at once: a
/// fault inside HDF5 or gmsh (thirdPartyFaultModule) is contained: one line "fuzz: contained
/// fault inside MODULE in the reader's child (pid P): SUMMARY" on stderr, the input kept as
/// $GSPH_FUZZ_CONTAINED_DIR/contained-P if that is set, and the child ends (exit status 86)
/// without an artifact. Any other report (our code, another library, a stack that cannot be
/// told) goes on to libFuzzer's callback: a crash-* artifact, a finding. The fuzzer's own
/// reports are untouched.
class ChildFaults {
  public:
    static constexpr int kContainedExitStatus = 86;
    ChildFaults() {
        char exe[4096];
        const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) executable_.assign(exe, static_cast<std::size_t>(n));
        if (const char* dir = std::getenv("GSPH_FUZZ_CONTAINED_DIR")) keepIn_ = dir;
        __asan_set_error_report_callback(&ChildFaults::onReport);
    }

  private:
    static void onReport(const char* report);
    pid_t fuzzer_ = ::getpid();
    std::string executable_;
    std::string keepIn_;
};

inline const ChildFaults childFaults;

inline void ChildFaults::onReport(const char* report) {
    if (::getpid() == childFaults.fuzzer_ || childFaults.executable_.empty()) return;
    const std::string module = thirdPartyFaultModule(report, childFaults.executable_);
    if (module.empty()) return;  // a finding: libFuzzer's death callback keeps the input
    const std::string_view text(report);
    std::string summary = "no summary";
    if (const std::size_t s = text.find("SUMMARY: "); s != std::string_view::npos)
        summary = std::string(text.substr(s, text.find('\n', s) - s));
    const std::string line = "fuzz: contained fault inside " + module +
                             " in the reader's child (pid " + std::to_string(::getpid()) +
                             "): " + summary + "\n";
    (void)!::write(2, line.data(), line.size());
    if (!childFaults.keepIn_.empty() && currentData != nullptr) {
        const std::string path = childFaults.keepIn_ + "/contained-" + std::to_string(::getpid());
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            (void)!::write(fd, currentData, currentSize);
            ::close(fd);
        }
    }
    ::_exit(ChildFaults::kContainedExitStatus);
}

/// Runs `read`; returns normally on success or a gsph::Error, aborts on any other exception.
template <class Read>
void expectTypedOutcome(Read&& read) {
    try {
        read();
    } catch (const gsph::Error&) {
        // The expected answer to a bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: untyped exception %s: %s\n", typeid(e).name(), e.what());
        std::abort();
    }
}

}  // namespace gsph::fuzz
