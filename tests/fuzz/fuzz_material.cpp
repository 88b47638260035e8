// SPDX-License-Identifier: MIT
// libFuzzer target: bytes → a material .toml → gsph::solver::readMaterialFile (docs/testing.md).
#include <cstddef>
#include <cstdint>

#include "entry_points.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = gsph::fuzz::writeScratch("fuzz_material.toml", data, size);
    gsph::fuzz::expectTypedOutcome([&] { gsph::fuzz::readMaterial(path); });
    return 0;
}
