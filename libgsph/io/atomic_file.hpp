// SPDX-License-Identifier: MIT
// Durable, atomic output files (style habit 11): every output is written under a temporary name
// in the target's folder, flushed to the device (fsync), optionally read back, and only then
// renamed onto the target; the folder is synced after the rename.
//
// Contract: after commit() the target holds the complete new file and survives a crash of the
// process or the machine (rename(2) is atomic within one file system, and both the file and its
// folder entry were synced). If anything fails before — a short write, a full disk (ENOSPC), a
// file-size limit (EFBIG), a failing fsync, the read-back check, an exception in the writer — the
// target is untouched (the last good file stays) and the temporary file is removed. Every
// failure throws IoError with one line naming the target and the operating system's reason.
// A process killed while writing leaves only its hidden temporary file
// (.NAME.tmp-PID-N), which removeStaleTemporaries() clears once that process is gone.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace gsph {

class AtomicFile {
  public:
    /// Chooses a unique temporary name next to `target` (nothing is created yet).
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Where the writer must write (a hidden file in the target's folder).
    const std::filesystem::path& tempPath() const { return temp_; }
    const std::filesystem::path& target() const { return target_; }

    /// Syncs the temporary file to the device, renames it onto the target and syncs the
    /// folder. Throws IoError if the temporary file is missing, or the sync or the rename
    /// fails (the temporary file is then removed).
    void commit();

  private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    bool committed_ = false;
};

/// Runs `write(tempPath)`, then `verify(tempPath)` if given (it throws if the file does not
/// read back), and commits; on any exception the temporary file is removed and the exception
/// propagates (a failing verify as IoError naming the target).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write,
                     const std::function<void(const std::filesystem::path&)>& verify = {});

/// Writes `bytes` to `path` (created or truncated) and checks every write and the close.
/// Throws IoError naming `reportAs` (default: `path`) and the OS error on failure.
void writeBytes(const std::filesystem::path& path, std::string_view bytes,
                const std::filesystem::path& reportAs = {});

/// writeAtomically of a text (history.csv, run.log, CSV tables).
void writeTextAtomically(const std::filesystem::path& target, std::string_view text);

/// Removes the temporary files that killed processes left in `folder` (hidden
/// .NAME.tmp-PID-N whose process no longer runs); returns how many. Never throws.
int removeStaleTemporaries(const std::filesystem::path& folder);

}  // namespace gsph
