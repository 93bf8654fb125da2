#include "formats/container_writer.h"

#include <cstring>
#include <string>

#include "formats/atomic_file.h"
#include "formats/checksum.h"
#include "formats/format_error.h"
#include "formats/section_ids.h"

namespace kdpm {

ContainerWriter::ContainerWriter(FileKind kind)
    : kind_(kind), major_(file_kind_info(kind).major), minor_(file_kind_info(kind).minor) {}

void ContainerWriter::set_version(std::uint16_t major, std::uint16_t minor) {
    major_ = major;
    minor_ = minor;
}

void ContainerWriter::add_raw(std::uint32_t id, ElementType type, std::uint32_t element_size,
                              std::uint64_t count, const void* data) {
    for (const auto& s : sections_)
        if (s.entry.id == id) throw FormatError("section " + std::to_string(id) + " added twice");
    if (element_size == 0) throw FormatError("section " + std::to_string(id) + " has element size 0");
    Pending p{};
    p.entry.id = id;
    p.entry.element_type = static_cast<std::uint32_t>(type);
    p.entry.element_size = element_size;
    p.entry.count = count;
    p.entry.byte_size = count * element_size;
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    p.data.assign(bytes, bytes + p.entry.byte_size);
    p.entry.checksum = checksum64(p.data.data(), p.data.size());
    sections_.push_back(std::move(p));
}

void ContainerWriter::set_metadata(const Metadata& m) {
    std::string json = metadata_to_json(m);
    add_raw(section::metadata, ElementType::text, 1, json.size(), json.data());
}

std::vector<std::uint8_t> ContainerWriter::bytes() const {
    std::vector<SectionEntry> table;
    std::uint64_t offset = align_up(sizeof(FileHeader), kSectionAlignment);
    for (const auto& s : sections_) {
        SectionEntry e = s.entry;
        e.offset = offset;
        table.push_back(e);
        offset = align_up(offset + e.byte_size, kSectionAlignment);
    }
    FileHeader h{};
    std::memcpy(h.magic, file_kind_info(kind_).magic, 8);
    h.version_major = major_;
    h.version_minor = minor_;
    h.endian_tag = kEndianTag;
    h.index_size = 4;
    h.float_size = 4;
    h.header_size = sizeof(FileHeader);
    h.section_entry_size = sizeof(SectionEntry);
    h.section_table_offset = offset;
    h.section_count = static_cast<std::uint32_t>(table.size());
    h.file_size = offset + table.size() * sizeof(SectionEntry);
    h.section_table_checksum = checksum64(table.data(), table.size() * sizeof(SectionEntry));
    h.header_checksum = checksum64(&h, kHeaderChecksummedBytes);

    std::vector<std::uint8_t> out(h.file_size, 0);  // gaps stay zero: the validator checks that
    std::memcpy(out.data(), &h, sizeof h);
    for (std::size_t i = 0; i < table.size(); ++i)
        if (!sections_[i].data.empty())
            std::memcpy(out.data() + table[i].offset, sections_[i].data.data(), sections_[i].data.size());
    if (!table.empty()) std::memcpy(out.data() + h.section_table_offset, table.data(), table.size() * sizeof(SectionEntry));
    return out;
}

void ContainerWriter::write(const std::filesystem::path& destination) const {
    const auto image = bytes();
    write_file_atomically(destination, [&](const ByteSink& sink) { sink(image.data(), image.size()); });
}

}  // namespace kdpm
