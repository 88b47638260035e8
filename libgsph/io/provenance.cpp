// SPDX-License-Identifier: MIT
#include "io/provenance.hpp"

#include <cstdint>

#include "core/error.hpp"
#include "io/sha256.hpp"

namespace gsph {

Provenance provenanceOf(const std::string& tool, const std::string& toolVersion,
                        const std::filesystem::path& source, const std::string& parameters) {
    Provenance p;
    p.tool = tool;
    p.toolVersion = toolVersion;
    p.sourceFile = source.string();
    p.sourceSha256 = sha256File(source);
    p.parameters = parameters;
    return p;
}

void writeProvenance(h5::File& file, const Provenance& p) {
    file.setAttribute("/", "tool", p.tool);
    file.setAttribute("/", "tool_version", p.toolVersion);
    file.setAttribute("/", "source_file", p.sourceFile);
    file.setAttribute("/", "source_sha256", p.sourceSha256);
    file.setAttribute("/", "source_parameters", p.parameters);
    file.setAttribute("/", "units", p.units);
}

void writeProvenance(ByteWriter& w, const Provenance& p) {
    w.texts({p.tool, p.toolVersion, p.sourceFile, p.sourceSha256, p.parameters, p.units});
}

Provenance readProvenance(ByteReader& r) {
    const std::vector<std::string> p = r.texts();
    if (p.size() != 6) throw IoError(r.source() + ": the reading process sent a bad answer");
    return {p[0], p[1], p[2], p[3], p[4], p[5]};
}

Provenance readProvenance(const h5::File& file) {
    auto get = [&](const char* name) {
        return file.hasAttribute("/", name) ? file.stringAttribute("/", name) : std::string();
    };
    Provenance p;
    p.tool = get("tool");
    p.toolVersion = get("tool_version");
    p.sourceFile = get("source_file");
    p.sourceSha256 = get("source_sha256");
    p.parameters = get("source_parameters");
    p.units = get("units");
    return p;
}

void writeFormatVersion(h5::File& file, const std::string& format, int major, int minor) {
    file.setAttribute("/", "format", format);
    file.setAttribute("/", "format_version_major", std::int64_t{major});
    file.setAttribute("/", "format_version_minor", std::int64_t{minor});
}

void checkFormatVersion(const h5::File& file, const std::string& format, int major) {
    if (!file.hasAttribute("/", "format") || file.stringAttribute("/", "format") != format)
        throw IoError(file.name() + ": not a " + format + " file");
    const auto found = file.integerAttribute("/", "format_version_major");
    if (found != major)
        throw IoError(file.name() + ": unsupported " + format + " major version " +
                      std::to_string(found) + " (this build reads " + std::to_string(major) + ")");
}

}  // namespace gsph
