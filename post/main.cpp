// SPDX-License-Identifier: MIT
// gsph-post: see README.md.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/version.hpp"

int main(int argc, char** argv) {
    CLI::App app{"gsph-post"};
    app.set_version_flag("--version", gsph::kVersion);
    CLI11_PARSE(app, argc, argv);
    std::cerr << "gsph-post: nothing to do yet\n";
    return 1;
}
