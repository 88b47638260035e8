// SPDX-License-Identifier: MIT
// libFuzzer target: bytes → a .msh → gsph::preproc::readHexMesh → convertHexMesh with the
// default options (docs/testing.md). gmsh's own parser runs uninstrumented; a crash inside it
// is gmsh's, one after it (the conversion) is ours.
#include <cstddef>
#include <cstdint>

#include "entry_points.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = gsph::fuzz::writeScratch("fuzz.msh", data, size);
    gsph::fuzz::expectTypedOutcome([&] { gsph::fuzz::readMesh(path); });
    return 0;
}
