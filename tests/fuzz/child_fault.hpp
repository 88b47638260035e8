// SPDX-License-Identifier: MIT
// Where the fault of a sanitizer report is: inside HDF5 or gmsh (a fault of theirs that the
// tools contain, because they run these parsers in a child process), or anywhere else (ours, or
// not known: a finding). Used by the fuzz targets in the reader's child (fuzz_support.hpp) and
// tested on its own (tests/tools/test_fuzz_regressions.cpp); scripts/fuzz applies the same rule
// to the inputs it re-runs.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace gsph::fuzz {

/// A stack frame (a line of a sanitizer report) in the C or C++ runtime.
inline bool inRuntimeLibrary(std::string_view frame) {
    for (const char* module : {"/libc.so", "/libstdc++.so", "/libgcc_s.so", "linux-vdso",
                               "/ld-linux", "/libm.so", "/libpthread.so"}) {
        if (frame.find(module) != std::string_view::npos) return true;
    }
    return false;
}

/// The module ("libhdf5_serial.so.103") of the fault in `report`, an AddressSanitizer report as
/// it prints it, if the fault is inside HDF5 or gmsh; "" otherwise. The fault is the first frame
/// of the report's first stack that is not in the C or C++ runtime (libc, libstdc++, libgcc_s,
/// the vDSO, the loader) nor in the executable's own runtime (the sanitizer's interceptors and
/// allocator, libFuzzer: a named frame "in NAME (EXECUTABLE+0x…)", without a source line). A
/// frame of a library names its module "(/…/libX.so+0x…)", with or without a function name.
/// A frame with a source line is code compiled here (ours, or a template of a header inlined
/// into ours): "". A nameless frame of the executable (not symbolized: ours or the runtime's),
/// another library's, or no such frame at all: not known, "".
inline std::string thirdPartyFaultModule(std::string_view report, std::string_view executable) {
    bool inStack = false;
    std::size_t at = 0;
    while (at < report.size()) {
        std::size_t end = report.find('\n', at);
        if (end == std::string_view::npos) end = report.size();
        const std::string_view line = report.substr(at, end - at);
        at = end + 1;
        const std::size_t hash = line.find_first_not_of(' ');
        const bool frame = hash != std::string_view::npos && line[hash] == '#' &&
                           line.find(" 0x", hash) != std::string_view::npos;
        if (!frame) {
            if (inStack) return "";  // the end of the first stack
            continue;
        }
        inStack = true;
        if (inRuntimeLibrary(line)) continue;
        const std::size_t module = line.find("(/");
        if (module != std::string_view::npos) {
            const std::size_t offset = line.find("+0x", module);
            const std::string_view path =
                line.substr(module + 1, offset == std::string_view::npos ? std::string_view::npos
                                                                         : offset - module - 1);
            if (path == executable) {
                // The executable's own frame without a source line: the runtime's if it is
                // named, else not known (our code, had it not been symbolized).
                if (line.find(" in ") == std::string_view::npos) return "";
                continue;
            }
            const std::size_t slash = path.rfind('/');
            const std::string_view file = path.substr(slash + 1);
            if (file.rfind("libhdf5", 0) == 0 || file.rfind("libgmsh", 0) == 0)
                return std::string(file);
        }
        return "";  // ours (a source line), or another library's
    }
    return "";
}

}  // namespace gsph::fuzz
