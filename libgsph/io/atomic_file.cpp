// SPDX-License-Identifier: MIT
#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace gsph {

namespace {

std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
    // Unique per process and per call: pid + a process-wide counter.
    static std::atomic<unsigned long> counter{0};
    // (Appended piecewise: GCC 12 at -O3 gives a false -Wrestrict on "." + std::string.)
    std::string name(1, '.');
    name.append(target.filename().string());
    name.append(".tmp-");
    name.append(std::to_string(::getpid()));
    name.append("-");
    name.append(std::to_string(counter++));
    return target.parent_path() / name;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) {
        throw IoError(target_.string() + ": output path names a folder, not a file");
    }
    const std::filesystem::path folder =
        target_.parent_path().empty() ? std::filesystem::path(".") : target_.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
        throw IoError(target_.string() + ": output folder " + folder.string() + " does not exist");
    }
    if (std::filesystem::is_directory(target_, ec)) {
        throw IoError(target_.string() + ": output path is a folder");
    }
    temp_ = temporaryNameFor(target_);
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        std::error_code ec;  // never throw from a destructor; nothing else to do on failure
        std::filesystem::remove(temp_, ec);
    }
}

void AtomicFile::commit() {
    std::error_code ec;
    if (!std::filesystem::exists(temp_, ec)) {
        throw IoError(target_.string() + ": nothing was written (temporary file missing)");
    }
    std::filesystem::rename(temp_, target_, ec);
    if (ec) {
        const std::string reason = ec.message();
        std::filesystem::remove(temp_, ec);
        throw IoError(target_.string() + ": cannot rename the temporary file onto it (" + reason +
                      ")");
    }
    committed_ = true;
}

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write) {
    AtomicFile file(target);
    write(file.tempPath());
    file.commit();
}

}  // namespace gsph
