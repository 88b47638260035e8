// SPDX-License-Identifier: MIT
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace gsph {

namespace {

constexpr const char* kTempTag = ".tmp-";

std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
    // Unique per process and per call: pid + a process-wide counter.
    static std::atomic<unsigned long> counter{0};
    // (Appended piecewise: GCC 12 at -O3 gives a false -Wrestrict on "." + std::string.)
    std::string name(1, '.');
    name.append(target.filename().string());
    name.append(kTempTag);
    name.append(std::to_string(::getpid()));
    name.append("-");
    name.append(std::to_string(counter++));
    return target.parent_path() / name;
}

std::filesystem::path folderOf(const std::filesystem::path& target) {
    return target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
}

[[noreturn]] void failWith(const std::filesystem::path& target, const std::string& what,
                           int error) {
    throw WriteError(target.string() + ": " + what + " (" + std::strerror(error) + ")");
}

// Flushes a file or a folder to the device (fsync on a read-only descriptor).
void syncPath(const std::filesystem::path& path, const std::filesystem::path& reportAs,
              bool folder) {
    const int fd = ::open(path.c_str(), (folder ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        failWith(reportAs, folder ? "cannot open its folder to sync it" : "cannot open to sync",
                 errno);
    if (::fsync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        // A folder on a file system that cannot sync folders (EINVAL) is not a lost write.
        if (!(folder && error == EINVAL)) failWith(reportAs, "sync to disk failed", error);
        return;
    }
    if (::close(fd) != 0) failWith(reportAs, "close failed", errno);
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) {
        throw IoError(target_.string() + ": output path names a folder, not a file");
    }
    const std::filesystem::path folder = folderOf(target_);
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
        throw WriteError(target_.string() + ": nothing was written (temporary file missing)");
    }
    syncPath(temp_, target_, false);
    std::filesystem::rename(temp_, target_, ec);
    if (ec) {
        const std::string reason = ec.message();
        std::filesystem::remove(temp_, ec);
        throw WriteError(target_.string() + ": cannot rename the temporary file onto it (" +
                         reason + ")");
    }
    committed_ = true;
    syncPath(folderOf(target_), target_, true);
}

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write,
                     const std::function<void(const std::filesystem::path&)>& verify) {
    AtomicFile file(target);
    write(file.tempPath());
    if (verify) {
        try {
            verify(file.tempPath());
        } catch (const std::exception& e) {
            throw WriteError(target.string() + ": the written file does not read back (" +
                             e.what() + "); the previous file is kept");
        }
    }
    file.commit();
}

void writeBytes(const std::filesystem::path& path, std::string_view bytes,
                const std::filesystem::path& reportAs) {
    const std::filesystem::path& name = reportAs.empty() ? path : reportAs;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) failWith(name, "cannot create", errno);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            ::close(fd);
            failWith(name,
                     "write failed after " + std::to_string(done) + " of " +
                         std::to_string(bytes.size()) + " bytes",
                     error);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0) failWith(name, "close failed", errno);
}

void writeTextAtomically(const std::filesystem::path& target, std::string_view text) {
    writeAtomically(target,
                    [&](const std::filesystem::path& temp) { writeBytes(temp, text, target); });
}

int removeStaleTemporaries(const std::filesystem::path& folder) {
    int removed = 0;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::size_t tag = name.rfind(kTempTag);
        if (name.empty() || name[0] != '.' || tag == std::string::npos) continue;
        // .NAME.tmp-PID-N: the process id between the tag and the last '-'.
        const std::size_t from = tag + std::strlen(kTempTag);
        const std::size_t dash = name.find('-', from);
        if (dash == std::string::npos || dash == from) continue;
        const std::string pidText = name.substr(from, dash - from);
        if (pidText.size() > 9 || pidText.find_first_not_of("0123456789") != std::string::npos)
            continue;
        const long pid = std::stol(pidText);
        const bool alive =
            pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
        if (alive) continue;
        std::error_code rm;
        if (std::filesystem::remove(it->path(), rm)) ++removed;
    }
    return removed;
}

}  // namespace gsph
