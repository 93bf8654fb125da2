#pragma once
// On-disk structs of the kdpm container (see formats/SPEC.md). Plain, fixed-size, little-endian.
#include <cstddef>
#include <cstdint>

namespace kdpm {

inline constexpr std::size_t kSectionAlignment = 64;
inline constexpr std::uint32_t kEndianTag = 0x01020304u;  // reads 04 03 02 01 on a little-endian disk

// Element types of a section: lets tools print and check sections they do not understand.
enum class ElementType : std::uint32_t {
    bytes = 0,   // opaque bytes (element size 1)
    u32 = 1,
    i32 = 2,
    f32 = 3,
    u64 = 4,
    f64 = 5,
    record = 6,  // a fixed-size struct described by the section id's layout header
    text = 7,    // UTF-8 text (element size 1)
};

struct FileHeader {
    char magic[8];                      // per file kind, e.g. "KDPM-GEO"
    std::uint16_t version_major;
    std::uint16_t version_minor;
    std::uint32_t endian_tag;           // kEndianTag
    std::uint8_t index_size;            // bytes of an index (4)
    std::uint8_t float_size;            // bytes of a float (4)
    std::uint16_t header_size;          // sizeof(FileHeader)
    std::uint32_t section_entry_size;   // sizeof(SectionEntry)
    std::uint64_t file_size;            // total bytes of the file
    std::uint64_t section_table_offset; // 64-byte aligned
    std::uint32_t section_count;
    std::uint32_t reserved0;
    std::uint64_t section_table_checksum;  // xxh3-64 of the section table bytes
    std::uint64_t reserved1[2];
    std::uint64_t header_checksum;      // xxh3-64 of the first 72 bytes (everything before this field)
};
static_assert(sizeof(FileHeader) == 80);

struct SectionEntry {
    std::uint32_t id;
    std::uint32_t element_type;   // ElementType
    std::uint32_t element_size;   // bytes per element
    std::uint32_t flags;          // reserved, 0
    std::uint64_t count;          // number of elements
    std::uint64_t offset;         // from the start of the file, 64-byte aligned
    std::uint64_t byte_size;      // count * element_size
    std::uint64_t checksum;       // xxh3-64 of the section's bytes
    std::uint64_t reserved[2];
};
static_assert(sizeof(SectionEntry) == 64);

inline constexpr std::size_t kHeaderChecksummedBytes = offsetof(FileHeader, header_checksum);

inline constexpr std::uint64_t align_up(std::uint64_t v, std::uint64_t a) { return (v + a - 1) / a * a; }

}  // namespace kdpm
