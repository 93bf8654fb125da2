#include "formats/container_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "formats/checksum.h"
#include "formats/section_ids.h"

namespace kdpm {
namespace {

std::string hex64(std::uint64_t v) {
    char buf[19];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

std::string version_text(unsigned major, unsigned minor) {
    return std::to_string(major) + "." + std::to_string(minor);
}

}  // namespace

std::string ContainerReader::section_label(std::uint32_t id) {
    auto n = section::name(id);
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", id);
    return n.empty() ? std::string(buf) : std::string(n) + " (" + buf + ")";
}

ContainerReader ContainerReader::open(const std::filesystem::path& path, std::optional<FileKind> expected) {
    ContainerReader r;
    r.mapping_ = MappedFile(path);
    r.bytes_ = r.mapping_.bytes();
    r.name_ = path.string();
    r.parse(expected);
    return r;
}

ContainerReader ContainerReader::from_bytes(std::span<const std::uint8_t> bytes, std::string name,
                                            std::optional<FileKind> expected) {
    ContainerReader r;
    r.owned_.resize((bytes.size() + 7) / 8);
    if (!bytes.empty()) std::memcpy(r.owned_.data(), bytes.data(), bytes.size());
    r.bytes_ = {reinterpret_cast<const std::uint8_t*>(r.owned_.data()), bytes.size()};
    r.name_ = std::move(name);
    r.parse(expected);
    return r;
}

void ContainerReader::parse(std::optional<FileKind> expected) {
    const std::uint64_t size = bytes_.size();
    auto fail = [&](const std::string& why) -> void { throw FormatError(name_ + ": " + why); };

    if (size < sizeof(FileHeader)) fail("not a kdpm file (too short: " + std::to_string(size) + " bytes)");
    std::memcpy(&header_, bytes_.data(), sizeof header_);
    auto kind = file_kind_from_magic(header_.magic);
    if (!kind) fail("not a kdpm file (unknown magic)");
    kind_ = *kind;
    const auto& info = file_kind_info(kind_);
    if (header_.endian_tag != kEndianTag) fail("wrong byte order or corrupt header");
    if (header_.header_size != sizeof(FileHeader) || header_.section_entry_size != sizeof(SectionEntry))
        fail("corrupt header (unexpected header or section entry size)");
    if (checksum64(&header_, kHeaderChecksummedBytes) != header_.header_checksum)
        fail("corrupt header (checksum mismatch)");
    if (header_.version_major != info.major)
        fail(std::string(info.name) + " format version " + version_text(header_.version_major, header_.version_minor) +
             " is not supported by this kdpm (reads " + version_text(info.major, info.minor) +
             "); rebuild it with: " + std::string(info.rebuild));
    if (expected && *expected != kind_)
        fail("is a " + std::string(info.name) + " file, expected a " + std::string(file_kind_info(*expected).name) +
             " file");
    if (header_.index_size != 4 || header_.float_size != 4) fail("unsupported index or float size");
    if (header_.file_size != size)
        fail("truncated or padded: header says " + std::to_string(header_.file_size) + " bytes, file has " +
             std::to_string(size));

    const std::uint64_t table_off = header_.section_table_offset;
    const std::uint64_t count = header_.section_count;
    if (table_off % kSectionAlignment != 0 || table_off < sizeof(FileHeader) || table_off > size)
        fail("corrupt header (section table offset out of range)");
    if (count > (size - table_off) / sizeof(SectionEntry) || table_off + count * sizeof(SectionEntry) != size)
        fail("corrupt header (section table does not end the file)");
    const std::uint8_t* table = bytes_.data() + table_off;
    if (checksum64(table, count * sizeof(SectionEntry)) != header_.section_table_checksum)
        fail("corrupt section table (checksum mismatch)");

    sections_.resize(count);
    if (count) std::memcpy(sections_.data(), table, count * sizeof(SectionEntry));
    const std::uint64_t data_begin = align_up(sizeof(FileHeader), kSectionAlignment);
    for (const auto& e : sections_) {
        const std::string label = "section " + section_label(e.id);
        if (e.offset % kSectionAlignment != 0) fail(label + " is not 64-byte aligned");
        if (e.element_size == 0) fail(label + " has element size 0");
        if (e.count > e.byte_size / e.element_size || e.count * e.element_size != e.byte_size)
            fail(label + " byte size does not match its count and element size");
        if (e.offset < data_begin || e.offset > table_off || e.byte_size > table_off - e.offset)
            fail(label + " lies outside the data area");
    }
    for (std::size_t i = 0; i < sections_.size(); ++i)
        for (std::size_t j = i + 1; j < sections_.size(); ++j)
            if (sections_[i].id == sections_[j].id) fail("section " + section_label(sections_[i].id) + " appears twice");
    std::vector<const SectionEntry*> order;
    for (const auto& e : sections_) order.push_back(&e);
    // Empty sections may share an offset with the next one: order them first so they overlap nothing.
    std::sort(order.begin(), order.end(), [](auto* a, auto* b) {
        return a->offset != b->offset ? a->offset < b->offset : a->byte_size < b->byte_size;
    });
    for (std::size_t i = 1; i < order.size(); ++i) {
        if (order[i - 1]->offset + order[i - 1]->byte_size > order[i]->offset)
            fail("sections " + section_label(order[i - 1]->id) + " and " + section_label(order[i]->id) + " overlap");
    }
}

const SectionEntry* ContainerReader::find(std::uint32_t id) const {
    for (const auto& e : sections_)
        if (e.id == id) return &e;
    return nullptr;
}

bool ContainerReader::has_metadata() const { return find(section::metadata) != nullptr; }

Metadata ContainerReader::metadata() const {
    const SectionEntry* e = find(section::metadata);
    if (!e) throw FormatError(name_ + ": no metadata section");
    auto b = section_bytes(*e);
    try {
        return metadata_from_json(std::string_view(reinterpret_cast<const char*>(b.data()), b.size()));
    } catch (const FormatError& err) {
        throw FormatError(name_ + ": " + err.what());
    }
}

void ContainerReader::verify() const {
    for (const auto& e : sections_) {
        auto b = section_bytes(e);
        std::uint64_t sum = checksum64(b.data(), b.size());
        if (sum != e.checksum)
            throw FormatError(name_ + ": section " + section_label(e.id) + " is corrupt (checksum " + hex64(sum) +
                              ", expected " + hex64(e.checksum) + ")");
    }
    // Padding must be zero: then no byte of the file escapes a check.
    std::vector<std::pair<std::uint64_t, std::uint64_t>> used{{0, sizeof(FileHeader)},
                                                             {header_.section_table_offset, bytes_.size()}};
    for (const auto& e : sections_) used.push_back({e.offset, e.offset + e.byte_size});
    std::sort(used.begin(), used.end());
    std::uint64_t cursor = 0;
    for (auto [begin, end] : used) {
        for (std::uint64_t i = cursor; i < begin; ++i)
            if (bytes_[i] != 0) throw FormatError(name_ + ": non-zero padding at byte " + std::to_string(i));
        cursor = std::max(cursor, end);
    }
    if (has_metadata()) (void)metadata();
}

}  // namespace kdpm
