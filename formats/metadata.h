#pragma once
// The metadata section: what made the file, from what, with which parameters.
// Only deterministic facts go here (no timestamps, no timings), so that the same inputs
// give byte-identical files.
#include <cstdint>
#include <map>
#include <string>

namespace kdpm {

struct Metadata {
    std::string tool;            // e.g. "kdpm-build-geometry"
    std::string tool_version;    // kdpm version
    std::string source_path;     // the input as given (file name only)
    std::string source_hash;     // xxh3-64 of the source bytes, 16 hex digits
    std::map<std::string, std::string> parameters;  // build parameters, as text
    std::map<std::string, double> statistics;       // build statistics (counts, costs)

    bool operator==(const Metadata&) const = default;
};

std::string metadata_to_json(const Metadata& m);
Metadata metadata_from_json(std::string_view json);  // throws FormatError

// Hex xxh3-64 of a whole file's bytes; throws FormatError when unreadable.
std::string hash_file(const std::string& path);

// The kdpm version string compiled into every tool.
const char* kdpm_version();

}  // namespace kdpm
