// SPDX-License-Identifier: MIT
// libFuzzer target: bytes → a .msh → gmsh's reader as gsph-preproc calls it (in a child process,
// readHexMeshInChild) → convertHexMesh with the default options (docs/testing.md): any crash,
// hang or sanitizer report is a finding. GSPH_FUZZ_IN_PROCESS=1 reads in this process
// (readHexMesh): gmsh's own parser runs uninstrumented; a crash inside it is gmsh's, one after
// it (the conversion) is ours.
#include <cstddef>
#include <cstdint>

#include "entry_points.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    gsph::fuzz::currentData = data;
    gsph::fuzz::currentSize = size;
    const auto path = gsph::fuzz::writeScratch("fuzz.msh", data, size);
    gsph::fuzz::expectTypedOutcome([&] {
        gsph::fuzz::parsersInProcess() ? gsph::fuzz::readMeshInProcess(path)
                                       : gsph::fuzz::readMesh(path);
    });
    return 0;
}
