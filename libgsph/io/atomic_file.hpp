// SPDX-License-Identifier: MIT
// Atomic output files (style habit 11): every output is written under a temporary name in the
// target's folder and renamed onto the target only once it is complete.
//
// Contract: after commit() the target holds the complete new file (rename(2) is atomic within
// one file system); if commit() is never reached (an exception, an early return) the destructor
// removes the temporary file, so a failed write leaves nothing behind and an existing target
// untouched. Throws IoError naming the target when the folder is missing or the rename fails.
#pragma once

#include <filesystem>
#include <functional>

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

    /// Renames the temporary file onto the target. Throws IoError if the temporary file is
    /// missing or the rename fails (the temporary file is then removed).
    void commit();

  private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    bool committed_ = false;
};

/// Runs `write(tempPath)` and commits; on any exception the temporary file is removed and the
/// exception propagates.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write);

}  // namespace gsph
