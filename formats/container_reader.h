#pragma once
// Reads a kdpm container from a memory mapping (or a caller's bytes), treating it as untrusted:
// header, version, section table, bounds, alignment and size/count consistency are checked on
// open, before any span is handed out. verify() also checks every checksum and padding byte.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "formats/container_layout.h"
#include "formats/file_kind.h"
#include "formats/format_error.h"
#include "formats/mapped_file.h"
#include "formats/metadata.h"

namespace kdpm {

class ContainerReader {
public:
    // Throws FormatError with a one-line reason. `expected` refuses files of another kind.
    static ContainerReader open(const std::filesystem::path& path,
                                std::optional<FileKind> expected = std::nullopt);
    // Over a copy of the caller's bytes (tests, fuzzer). `name` is used in messages.
    static ContainerReader from_bytes(std::span<const std::uint8_t> bytes, std::string name,
                                      std::optional<FileKind> expected = std::nullopt);

    FileKind kind() const { return kind_; }
    const FileHeader& header() const { return header_; }
    const std::vector<SectionEntry>& sections() const { return sections_; }
    const std::string& name() const { return name_; }
    std::span<const std::uint8_t> file_bytes() const { return bytes_; }

    const SectionEntry* find(std::uint32_t id) const;
    std::span<const std::uint8_t> section_bytes(const SectionEntry& e) const {
        return bytes_.subspan(e.offset, e.byte_size);
    }

    // Typed view of a section; throws when it is missing or its element size is not sizeof(T).
    template <class T>
    std::span<const T> section(std::uint32_t id) const {
        auto s = optional_section<T>(id);
        if (!s) throw FormatError(name_ + ": missing section " + section_label(id));
        return *s;
    }
    template <class T>
    std::optional<std::span<const T>> optional_section(std::uint32_t id) const {
        const SectionEntry* e = find(id);
        if (!e) return std::nullopt;
        if (e->element_size != sizeof(T))
            throw FormatError(name_ + ": section " + section_label(id) + " has element size " +
                              std::to_string(e->element_size) + ", expected " + std::to_string(sizeof(T)));
        return std::span<const T>(reinterpret_cast<const T*>(bytes_.data() + e->offset), e->count);
    }
    // Exactly one record.
    template <class T>
    const T& record(std::uint32_t id) const {
        auto s = section<T>(id);
        if (s.size() != 1) throw FormatError(name_ + ": section " + section_label(id) + " must hold one record");
        return s[0];
    }

    bool has_metadata() const;
    Metadata metadata() const;  // throws when missing or malformed

    // Every section checksum, and that all bytes between sections are zero. Throws FormatError.
    void verify() const;

    static std::string section_label(std::uint32_t id);

private:
    ContainerReader() = default;
    void parse(std::optional<FileKind> expected);

    MappedFile mapping_;
    std::vector<std::uint64_t> owned_;  // 8-byte aligned copy for from_bytes
    std::span<const std::uint8_t> bytes_;
    std::string name_;
    FileHeader header_{};
    FileKind kind_{};
    std::vector<SectionEntry> sections_;
};

}  // namespace kdpm
