// SPDX-License-Identifier: MIT
// Provenance that every file the tools write carries (DESIGN §1): the writing tool and its
// version, the source file and its SHA-256, the parameters that changed the source, the units.
// Stored as attributes of the file's root group; see docs/formats.md.
#pragma once

#include <filesystem>
#include <string>

#include "io/child_process.hpp"
#include "io/hdf5_file.hpp"

namespace gsph {

struct Provenance {
    std::string tool;          ///< writing tool, e.g. "gsph-preproc"
    std::string toolVersion;   ///< gsph::kVersion of that tool
    std::string sourceFile;    ///< the input file, as named on the command line
    std::string sourceSha256;  ///< SHA-256 of the input file's bytes (lower-case hex)
    std::string parameters;    ///< parameters applied to the input ("refine=2"), or empty
    std::string units = "SI";  ///< unit system of every dimensional value in the file
};

/// Provenance of a file produced by `tool` from `source`; hashes the source (throws IoError if
/// it cannot be read).
Provenance provenanceOf(const std::string& tool, const std::string& toolVersion,
                        const std::filesystem::path& source, const std::string& parameters = "");

/// Root attributes tool, tool_version, source_file, source_sha256, source_parameters, units.
void writeProvenance(h5::File& file, const Provenance& provenance);
/// Reads them back; missing attributes stay empty (units default "SI" only if written so).
Provenance readProvenance(const h5::File& file);

/// The six strings through a child process's byte stream (io/child_process.hpp).
void writeProvenance(ByteWriter& w, const Provenance& provenance);
Provenance readProvenance(ByteReader& r);

/// Root attributes format, format_version_major, format_version_minor (snapshots, checkpoints).
void writeFormatVersion(h5::File& file, const std::string& format, int major, int minor);
/// Throws IoError naming the file unless its root says `format` with major version `major`.
void checkFormatVersion(const h5::File& file, const std::string& format, int major);

}  // namespace gsph
