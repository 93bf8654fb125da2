#pragma once
// Rewrites a kdpm file with one section changed and every checksum recomputed, so a test can
// hand the validator a file whose only defect is the value it plants.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <vector>

#include "formats/container_reader.h"
#include "formats/container_writer.h"

namespace kdpm::test {

struct EditableSection {
    std::uint32_t id;
    std::uint32_t element_type;
    std::uint32_t element_size;
    std::uint64_t count;
    std::vector<std::uint8_t> data;
};

inline void reseal(const std::filesystem::path& in, const std::filesystem::path& out,
                   const std::function<void(EditableSection&)>& edit) {
    const ContainerReader r = ContainerReader::open(in);
    ContainerWriter w(r.kind());
    for (const SectionEntry& e : r.sections()) {
        const auto bytes = r.section_bytes(e);
        EditableSection s{e.id, e.element_type, e.element_size, e.count, {bytes.begin(), bytes.end()}};
        edit(s);
        w.add_raw(s.id, static_cast<ElementType>(s.element_type), s.element_size, s.count, s.data.data());
    }
    w.write(out);
}

// Edits the first record of section `id` as a T.
template <class T>
void reseal_record(const std::filesystem::path& in, const std::filesystem::path& out, std::uint32_t id,
                   const std::function<void(T&)>& edit) {
    reseal(in, out, [&](EditableSection& s) {
        if (s.id != id) return;
        T record;
        std::memcpy(&record, s.data.data(), sizeof(T));
        edit(record);
        std::memcpy(s.data.data(), &record, sizeof(T));
    });
}

}  // namespace kdpm::test
