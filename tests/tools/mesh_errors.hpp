// SPDX-License-Identifier: MIT
// The preprocessor's error contract on a fixture of tests/data: reading and converting it throws
// `Error` with one line that starts with the file's path. Needs GSPH_SOURCE_DIR.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "conversion.hpp"
#include "gmsh_input.hpp"

namespace gsph::test {

/// Reads and converts tests/data/`file` with the given .geo parameters; returns the error
/// message, "" (and a test failure) if none.
template <class Error>
std::string meshErrorOf(const std::string& file,
                        const std::vector<std::pair<std::string, double>>& parameters = {}) {
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/tests/data/" + file;
    try {
        std::vector<std::string> warnings;
        preproc::convertHexMesh(
            preproc::readHexMesh(path, preproc::MeshReadOptions{parameters}, warnings));
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u)
            << "the message must start with the file: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    }
    ADD_FAILURE() << file << ": no error";
    return "";
}

}  // namespace gsph::test
