// SPDX-License-Identifier: MIT
// What every fuzz target shares: a scratch folder of its own process, and the verdict on an
// input. A gsph::Error is the expected answer to bad input; any other exception is reported and
// aborts, so that libFuzzer keeps the input as a crash (the library promises typed errors).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

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
