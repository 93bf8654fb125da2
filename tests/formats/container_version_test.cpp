#include <catch2/catch.hpp>

#include "formats/container_reader.h"
#include "tests/formats/sample_container.h"

using namespace kdpm;

TEST_CASE("another major version is refused with both versions and the rebuild command", "[formats]") {
    auto w = test::sample_writer();
    const auto& info = file_kind_info(FileKind::test);
    w.set_version(static_cast<std::uint16_t>(info.major + 1), 0);
    auto bytes = w.bytes();
    try {
        ContainerReader::from_bytes(bytes, "future.kdt");
        FAIL("a newer major version was accepted");
    } catch (const FormatError& e) {
        std::string msg = e.what();
        CHECK_THAT(msg, Catch::Contains(std::to_string(info.major + 1) + ".0"));
        CHECK_THAT(msg, Catch::Contains(std::to_string(info.major) + "." + std::to_string(info.minor)));
        CHECK_THAT(msg, Catch::Contains(std::string(info.rebuild)));
        CHECK(msg.find('\n') == std::string::npos);
    }
}

TEST_CASE("a newer minor version is read and its unknown sections skipped", "[formats]") {
    auto w = test::sample_writer();
    const auto& info = file_kind_info(FileKind::test);
    w.set_version(info.major, static_cast<std::uint16_t>(info.minor + 3));
    std::vector<double> future{1.0, 2.0};
    w.add(0xEEEE, ElementType::f64, future);
    auto bytes = w.bytes();
    auto r = ContainerReader::from_bytes(bytes, "newer.kdt");
    CHECK(r.header().version_minor == info.minor + 3);
    CHECK(r.section<std::uint32_t>(section::test_first).size() == 5);
    CHECK(r.metadata() == test::sample_metadata());
    CHECK_NOTHROW(r.verify());
}
