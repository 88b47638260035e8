// SPDX-License-Identifier: MIT
// libFuzzer target: bytes → case.toml → gsph::solver::readCaseFile (docs/testing.md).
#include <cstddef>
#include <cstdint>

#include "entry_points.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = gsph::fuzz::writeScratch("case.toml", data, size);
    gsph::fuzz::expectTypedOutcome([&] { gsph::fuzz::readCase(path); });
    return 0;
}
