#pragma once
// Assembles sections into a kdpm container and writes it atomically.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "formats/container_layout.h"
#include "formats/file_kind.h"
#include "formats/metadata.h"

namespace kdpm {

class ContainerWriter {
public:
    explicit ContainerWriter(FileKind kind);

    // Tests write other versions to check the reader's version rule.
    void set_version(std::uint16_t major, std::uint16_t minor);

    void add_raw(std::uint32_t id, ElementType type, std::uint32_t element_size, std::uint64_t count,
                 const void* data);

    template <class T>
    void add(std::uint32_t id, ElementType type, std::span<const T> items) {
        add_raw(id, type, sizeof(T), items.size(), items.data());
    }
    template <class T>
    void add(std::uint32_t id, ElementType type, const std::vector<T>& items) {
        add(id, type, std::span<const T>(items));
    }
    template <class T>
    void add_record(std::uint32_t id, const T& record) {
        add_raw(id, ElementType::record, sizeof(T), 1, &record);
    }

    void set_metadata(const Metadata& m);

    // The complete file image (for tests and the fuzzer's seed).
    std::vector<std::uint8_t> bytes() const;

    // Atomic: the destination is either the complete new file or untouched. Throws FormatError.
    void write(const std::filesystem::path& destination) const;

private:
    struct Pending {
        SectionEntry entry;
        std::vector<std::uint8_t> data;
    };
    FileKind kind_;
    std::uint16_t major_, minor_;
    std::vector<Pending> sections_;
};

}  // namespace kdpm
