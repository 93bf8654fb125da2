// Numbers checked at the boundary: camera and light values in cards and .kdg files, defaults
// held to the limits of the options they stand in for, scenes too large for float arithmetic,
// and metadata that is not what it claims.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include <rapidjson/document.h>

#include "formats/geometry_layout.h"
#include "formats/metadata.h"
#include "formats/section_ids.h"
#include "tests/hostile/hostile_files.h"
#include "tests/hostile/resealed_file.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// One lit triangle: the Cornell box is more than these tests need.
const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

test::CommandResult build_card(const test::TempDir& dir, const std::string& extra, const std::string& prefix = "") {
    test::write_file(dir / "tri.obj", kTriangleObj);
    test::write_file(dir / "card.json", prefix + test::card_json("tri.obj", extra));
    return test::run_tool("kdpm-build-geometry '" + (dir / "card.json").string() + "' -o '" +
                          (dir / "out.kdg").string() + "' --quiet");
}

std::string camera(const std::string& eye, const std::string& lookat, const std::string& up, const std::string& vfov = "40") {
    return "\"camera\": {\"eye\": " + eye + ", \"lookat\": " + lookat + ", \"up\": " + up + ", \"vfov\": " + vfov + "}";
}

test::CommandResult validate(const fs::path& p) { return test::run_tool("kdpm-validate '" + p.string() + "'"); }

}  // namespace

TEST_CASE("cards with degenerate cameras are refused at build time", "[hostile][numbers]") {
    test::TempDir dir;
    struct Case {
        std::string camera, expected;
    };
    const Case cases[] = {
        {camera("[0,0,4]", "[0,0,0]", "[0,0,1]"), "parallel"},
        {camera("[0,0,4]", "[0,0,4]", "[0,1,0]"), "same point"},
        {camera("[0,0,4]", "[0,0,0]", "[0,0,0]"), "zero vector"},
        {camera("[1e300,0,4]", "[0,0,0]", "[0,1,0]"), "does not fit a float"},
        {camera("[0,0,4]", "[0,0,0]", "[0,1,0]", "\"wide\""), "vfov"},
    };
    for (const Case& c : cases) {
        INFO(c.camera);
        const auto r = build_card(dir, c.camera);
        CHECK(test::is_clean_error(r));
        CHECK_THAT(r.output, Catch::Contains(c.expected));
    }
    CHECK(build_card(dir, camera("[0,0,4]", "[0,0,0]", "[0,1,0]")).exit_code == 0);
}

TEST_CASE("card defaults obey the limits of the options they stand in for", "[hostile][numbers]") {
    test::TempDir dir;
    for (const char* extra : {"\"bounces\": 1000", "\"k\": 4096", "\"photons\": 4294967295",
                              "\"camera\": {\"eye\": [0,0,4], \"lookat\": [0,0,0], \"up\": [0,1,0], \"vfov\": 40, "
                              "\"width\": 65536, \"height\": 64}"}) {
        INFO(extra);
        CHECK(test::is_clean_error(build_card(dir, extra)));
    }
    CHECK(build_card(dir, "\"bounces\": 255, \"k\": 256").exit_code == 0);
}

TEST_CASE("a card light whose area overflows is named as such", "[hostile][numbers]") {
    test::TempDir dir;
    const auto r = build_card(dir, "\"lights\": [{\"p0\": [0,2,0], \"e1\": [1e20,0,0], \"e2\": [0,0,1e20], "
                                   "\"radiance\": [1,1,1]}]");
    CHECK(test::is_clean_error(r));
    CHECK_THAT(r.output, Catch::Contains("overflows"));
}

TEST_CASE("a card with a UTF-8 byte order mark is read", "[hostile][numbers]") {
    test::TempDir dir;
    const auto r = build_card(dir, "", "\xEF\xBB\xBF");
    CHECK(r.exit_code == 0);
}

TEST_CASE("a scene scaled by 1e30 is an error at build time, not a NaN tree", "[hostile][numbers]") {
    test::TempDir dir;
    test::write_file(dir / "huge.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nf 1 2 3\n");
    const auto r = test::run_tool("kdpm-build-geometry '" + (dir / "huge.obj").string() + "' -o '" +
                                  (dir / "out.kdg").string() + "' --quiet");
    CHECK(test::is_clean_error(r));
    CHECK_THAT(r.output, Catch::Contains("scale it down"));
}

TEST_CASE("the validator refuses what it used to report as ok", "[hostile][numbers]") {
    test::TempDir dir;
    REQUIRE(build_card(dir, "\"lights\": [{\"p0\": [0,2,0], \"e1\": [1,0,0], \"e2\": [0,0,1], "
                            "\"radiance\": [1,1,1]}]")
                .exit_code == 0);
    const fs::path good = dir / "out.kdg", bad = dir / "bad.kdg";
    REQUIRE(validate(good).exit_code == 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* what;
        std::function<void()> plant;
    };
    const Case cases[] = {
        {"NaN light power", [&] { test::reseal_record<AreaLightRecord>(good, bad, section::geo_lights, [&](auto& l) { l.power = nan; }); }},
        {"infinite light area", [&] { test::reseal_record<AreaLightRecord>(good, bad, section::geo_lights, [](auto& l) { l.area = INFINITY; }); }},
        {"unknown triangle flags", [&] { test::reseal_record<TriangleRecord>(good, bad, section::geo_triangles, [](auto& t) { t.flags |= 0x80u; }); }},
        {"source index out of range", [&] { test::reseal_record<TriangleRecord>(good, bad, section::geo_triangles, [](auto& t) { t.source_index = 7; }); }},
        {"camera up parallel to the view", [&] { test::reseal_record<CameraRecord>(good, bad, section::geo_camera, [](auto& c) {
             for (int a = 0; a < 3; ++a) c.up[a] = c.lookat[a] - c.eye[a]; }); }},
        {"NaN eye", [&] { test::reseal_record<CameraRecord>(good, bad, section::geo_camera, [&](auto& c) { c.eye[0] = nan; }); }},
        {"default photons 0xffffffff", [&] { test::reseal_record<GeometryInfo>(good, bad, section::geo_info, [](auto& i) { i.default_photons = 0xffffffffu; }); }},
        {"wrong element type", [&] { test::reseal(good, bad, [](test::EditableSection& s) {
             if (s.id == section::geo_leaf_indices) s.element_type = static_cast<std::uint32_t>(ElementType::f32); }); }},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        c.plant();
        const auto r = validate(bad);
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.output, Catch::Contains("invalid geometry file"));
        // The renderer loads through the same checks.
        CHECK(test::run_tool("kdpm-render '" + bad.string() + "' --mode direct -o '" + (dir / "x.png").string() + "' --quiet")
                  .exit_code == 1);
    }
}

TEST_CASE("garbage metadata gets a reason, not a parser assertion", "[hostile][numbers]") {
    test::TempDir dir;
    REQUIRE(build_card(dir, "").exit_code == 0);
    const fs::path bad = dir / "bad.kdg";
    test::reseal(dir / "out.kdg", bad, [](test::EditableSection& s) {
        if (s.id != section::metadata) return;
        const std::string junk = "[1, 2, 3]";
        s.data.assign(junk.begin(), junk.end());
        s.count = junk.size();
    });
    const auto r = test::run_tool("kdpm-inspect '" + bad.string() + "'");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Catch::Contains("no \"kdpm\" object"));
    CHECK_THAT(r.output, !Catch::Contains("assertion"));
}

TEST_CASE("copies of one triangle are held once in the tree, with a warning", "[hostile][numbers]") {
    test::TempDir dir;
    // 200,000 copies of one triangle beside a second one: before, one leaf held every copy and
    // each ray through it tested them all.
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 2 2\nv 3 2 2\nv 2 3 2\nf 4 5 6\n";
    obj.reserve(obj.size() + 200000 * 8);
    for (int i = 0; i < 200000; ++i) obj += "f 1 2 3\n";
    test::write_file(dir / "copies.obj", obj);
    const auto r = test::run_tool("kdpm-build-geometry '" + (dir / "copies.obj").string() + "' -o '" +
                                  (dir / "out.kdg").string() + "'");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("warning: 199999 triangles are exact copies of earlier ones"));
    CHECK_THAT(r.output, !Catch::Contains("a leaf holds"));
    CHECK(validate(dir / "out.kdg").exit_code == 0);
    const auto inspect = test::run_tool("kdpm-inspect --json '" + (dir / "out.kdg").string() + "'");
    REQUIRE(inspect.exit_code == 0);
    rapidjson::Document doc;
    doc.Parse(inspect.output.c_str());
    REQUIRE_FALSE(doc.HasParseError());
    const auto& stats = doc["metadata"]["kdpm"]["statistics"];
    CHECK(stats["repeated_triangles"].GetDouble() == 199999.0);
    CHECK(stats["leaf_references"].GetDouble() <= 2.0);
}

TEST_CASE("metadata with a NaN statistic is still valid JSON (kdpm-inspect --json)", "[hostile][numbers]") {
    Metadata m;
    m.tool = "kdpm-build-geometry";
    m.statistics["sah_cost"] = std::numeric_limits<double>::quiet_NaN();
    m.statistics["nodes"] = 3;
    const std::string json = metadata_to_json(m);
    rapidjson::Document doc;
    doc.Parse(json.c_str());
    CHECK_FALSE(doc.HasParseError());
    const Metadata back = metadata_from_json(json);
    CHECK(back.statistics.count("nodes") == 1);
    CHECK(back.statistics.count("sah_cost") == 0);
}
