#include <catch2/catch.hpp>

#include <cstring>

#include "formats/container_reader.h"
#include "formats/checksum.h"
#include "tests/formats/sample_container.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("a written container reads back every field", "[formats]") {
    test::TempDir dir;
    auto path = dir / "sample.kdt";
    test::sample_writer().write(path);

    auto r = ContainerReader::open(path, FileKind::test);
    const auto& h = r.header();
    CHECK(r.kind() == FileKind::test);
    CHECK(std::memcmp(h.magic, "KDPM-TST", 8) == 0);
    CHECK(h.version_major == file_kind_info(FileKind::test).major);
    CHECK(h.version_minor == file_kind_info(FileKind::test).minor);
    CHECK(h.endian_tag == kEndianTag);
    CHECK(h.index_size == 4);
    CHECK(h.float_size == 4);
    CHECK(h.file_size == std::filesystem::file_size(path));
    CHECK(h.section_count == 5);
    CHECK(h.section_table_offset % kSectionAlignment == 0);

    auto ints = r.section<std::uint32_t>(section::test_first + 0);
    CHECK(std::vector<std::uint32_t>(ints.begin(), ints.end()) == std::vector<std::uint32_t>{1, 2, 3, 4, 5});
    auto floats = r.section<float>(section::test_first + 1);
    CHECK(std::vector<float>(floats.begin(), floats.end()) == std::vector<float>{0.5f, -1.25f, 3.0f});
    auto recs = r.section<test::SampleRecord>(section::test_first + 2);
    REQUIRE(recs.size() == 2);
    CHECK(recs[1].a[2] == 6.0f);
    CHECK(recs[1].b == 9u);
    CHECK(r.section<std::uint32_t>(section::test_first + 3).empty());

    for (const auto& e : r.sections()) {
        CHECK(e.offset % kSectionAlignment == 0);
        CHECK(reinterpret_cast<std::uintptr_t>(r.section_bytes(e).data()) % kSectionAlignment == 0);
        CHECK(e.byte_size == e.count * e.element_size);
        auto b = r.section_bytes(e);
        CHECK(e.checksum == checksum64(b.data(), b.size()));
    }
    CHECK(r.metadata() == test::sample_metadata());
    CHECK_NOTHROW(r.verify());
}

TEST_CASE("the writer is deterministic", "[formats]") {
    CHECK(test::sample_writer().bytes() == test::sample_writer().bytes());
}

TEST_CASE("typed access checks element size and presence", "[formats]") {
    auto bytes = test::sample_writer().bytes();
    auto r = ContainerReader::from_bytes(bytes, "sample");
    CHECK_THROWS_AS(r.section<std::uint64_t>(section::test_first + 0), FormatError);
    CHECK_THROWS_WITH(r.section<float>(0xABC), Catch::Contains("missing section"));
    CHECK_FALSE(r.optional_section<float>(0xABC).has_value());
}

TEST_CASE("a file of another kind is refused by name", "[formats]") {
    auto bytes = test::sample_writer().bytes();
    CHECK_THROWS_WITH(ContainerReader::from_bytes(bytes, "sample", FileKind::geometry),
                      Catch::Contains("expected a geometry kd-tree file"));
}

TEST_CASE("metadata JSON round trips and rejects junk", "[formats]") {
    auto m = test::sample_metadata();
    CHECK(metadata_from_json(metadata_to_json(m)) == m);
    CHECK_THROWS_AS(metadata_from_json("{not json"), FormatError);
    CHECK_THROWS_AS(metadata_from_json(std::string(100000, '[')), FormatError);
}
