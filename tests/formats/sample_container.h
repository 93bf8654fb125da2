#pragma once
// A small container with every element type and metadata, shared by the format tests.
#include <cstdint>
#include <string>
#include <vector>

#include "formats/container_writer.h"
#include "formats/section_ids.h"

namespace kdpm::test {

struct SampleRecord {
    float a[3];
    std::uint32_t b;
};

inline Metadata sample_metadata() {
    Metadata m;
    m.tool = "kdpm-test";
    m.tool_version = kdpm_version();
    m.source_path = "sample.obj";
    m.source_hash = "0123456789abcdef";
    m.parameters = {{"cost.traversal", "1"}, {"max_depth", "40"}};
    m.statistics = {{"nodes", 17}, {"sah_cost", 12.5}};
    return m;
}

inline ContainerWriter sample_writer() {
    ContainerWriter w(FileKind::test);
    std::vector<std::uint32_t> ints{1, 2, 3, 4, 5};
    std::vector<float> floats{0.5f, -1.25f, 3.0f};
    std::vector<SampleRecord> records{{{1, 2, 3}, 7}, {{4, 5, 6}, 9}};
    w.add(section::test_first + 0, ElementType::u32, ints);
    w.add(section::test_first + 1, ElementType::f32, floats);
    w.add(section::test_first + 2, ElementType::record, records);
    w.add(section::test_first + 3, ElementType::u32, std::vector<std::uint32_t>{});  // empty section
    w.set_metadata(sample_metadata());
    return w;
}

}  // namespace kdpm::test
