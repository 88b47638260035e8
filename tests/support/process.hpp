// SPDX-License-Identifier: MIT
// Runs a command line through /bin/sh and captures its exit status, stdout and stderr (tests of
// the tools run them as a user does).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/temp_dir.hpp"

namespace gsph::test {

struct ProcessResult {
    int status = -1;  ///< exit code, −1 if the process did not exit normally
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// 'text' for the shell (built by appending: GCC 12 warns falsely on "'" + std::string&&).
inline std::string quote(const std::string& text) {
    std::string q(1, '\'');
    q.append(text);
    q.push_back('\'');
    return q;
}

/// Runs `command`; stdout and stderr go to a scratch folder of their own.
inline ProcessResult runCommand(const std::string& command) {
    TempDir logs;
    const std::string full =
        command + " > " + quote((logs / "out").string()) + " 2> " + quote((logs / "err").string());
    const int raw = std::system(full.c_str());
    ProcessResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(logs / "out");
    r.err = slurp(logs / "err");
    return r;
}

}  // namespace gsph::test
