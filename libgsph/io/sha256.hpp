// SPDX-License-Identifier: MIT
// SHA-256 (FIPS 180-4) of bytes and files, for the provenance every output file carries
// (DESIGN §1: "source file, its hash"). Self-contained so the library needs no crypto package.
//
// Contract: sha256Hex returns the 64-character lower-case hexadecimal digest; the streaming
// Sha256 class gives the same digest whatever the chunking of update() calls. sha256File reads
// the file in chunks (constant memory) and throws IoError if it cannot be read.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace gsph {

/// Streaming SHA-256: update() any number of times, then hexDigest() once.
class Sha256 {
  public:
    Sha256();
    void update(std::span<const std::uint8_t> bytes);
    void update(std::string_view text);
    /// Finishes the hash and returns the digest in lower-case hex. The object is spent after.
    std::string hexDigest();

  private:
    void compress(const std::uint8_t* block);

    std::array<std::uint32_t, 8> state_;
    std::array<std::uint8_t, 64> buffer_{};
    std::size_t buffered_ = 0;
    std::uint64_t totalBytes_ = 0;
};

/// SHA-256 of a byte string, lower-case hex.
std::string sha256Hex(std::string_view bytes);

/// SHA-256 of a file's contents, lower-case hex. Throws IoError naming the file on failure.
std::string sha256File(const std::filesystem::path& path);

}  // namespace gsph
