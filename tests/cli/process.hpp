// SPDX-License-Identifier: MIT
// Runs a command line and captures its exit code, stdout and stderr (tests of the tools).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace gsph::test {

struct ProcessResult {
    int exitCode = -1;
    std::string out, err;
};

/// Runs `command` through /bin/sh, stderr captured through a temporary file.
inline ProcessResult runCommand(const std::string& command, const std::string& scratch) {
    const std::string errFile = scratch + "/stderr.txt";
    ProcessResult r;
    FILE* pipe = popen((command + " 2>" + errFile).c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe)) r.out += buf.data();
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(errFile);
    std::stringstream ss;
    ss << in.rdbuf();
    r.err = ss.str();
    return r;
}

}  // namespace gsph::test
