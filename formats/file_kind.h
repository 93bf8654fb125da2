#pragma once
// The kinds of kdpm file: magic, current version, and the command that rebuilds each.
#include <cstdint>
#include <optional>
#include <string_view>

namespace kdpm {

enum class FileKind : std::uint8_t { geometry, photon_hits, photon_tree, test };

struct FileKindInfo {
    FileKind kind;
    char magic[8];
    std::uint16_t major;
    std::uint16_t minor;
    std::string_view name;      // human name
    std::string_view extension; // conventional extension
    std::string_view rebuild;   // command that makes this kind of file
};

const FileKindInfo& file_kind_info(FileKind kind);
std::optional<FileKind> file_kind_from_magic(const char (&magic)[8]);

}  // namespace kdpm
