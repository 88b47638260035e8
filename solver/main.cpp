// SPDX-License-Identifier: MIT
// gsph-solver: see README.md.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/version.hpp"

int main(int argc, char** argv) {
    CLI::App app{"gsph-solver"};
    app.set_version_flag("--version", gsph::kVersion);
    CLI11_PARSE(app, argc, argv);
    std::cerr << "gsph-solver: nothing to do yet\n";
    return 1;
}
