// The metadata section's text is what cereal's JSON archive wrote for it before kdpm wrote it with
// RapidJSON directly: the same bytes, so files stay identical to those of earlier builds. The
// reference here is cereal's archive itself, the way kdpm used it.
#include <catch2/catch.hpp>

#include <cereal/archives/json.hpp>
#include <cereal/types/string.hpp>

#include <limits>
#include <sstream>
#include <string>

#include "formats/metadata.h"

using namespace kdpm;

namespace {

template <class T>
void save_object(cereal::JSONOutputArchive& ar, const char* name, const std::map<std::string, T>& map) {
    ar.setNextName(name);
    ar.startNode();
    for (const auto& [k, v] : map) ar(cereal::make_nvp(k, v));
    ar.finishNode();
}

struct CerealMetadata {
    const Metadata& m;
    template <class Archive>
    void save(Archive& ar) const {
        ar(cereal::make_nvp("tool", m.tool), cereal::make_nvp("tool_version", m.tool_version),
           cereal::make_nvp("source_path", m.source_path), cereal::make_nvp("source_hash", m.source_hash));
        save_object(ar, "parameters", m.parameters);
        save_object(ar, "statistics", m.statistics);
    }
};

std::string cereal_text(const Metadata& m) {
    std::ostringstream out;
    {
        cereal::JSONOutputArchive ar(out, cereal::JSONOutputArchive::Options::Default());
        ar(cereal::make_nvp("kdpm", CerealMetadata{m}));
    }
    return out.str();
}

}  // namespace

TEST_CASE("metadata text is byte for byte cereal's JSON archive's", "[formats]") {
    Metadata m;
    CHECK(metadata_to_json(m) == cereal_text(m));  // empty strings and objects
    m.tool = "kdpm-build-geometry";
    m.tool_version = kdpm_version();
    m.source_path = "dir with \"quotes\"\\back\tslash\n\x01 \xc3\xa9t\xc3\xa9.obj";
    m.source_hash = "9b4ff5120fa41f8d";
    m.parameters = {{"empty_bonus", "0.200000003"}, {"quality", "fast"}, {"", ""}, {"\xe2\x82\xac", "\x7f"}};
    m.statistics = {{"nodes", 373445},
                    {"sah_cost", 74.33341217041016},
                    {"tiny", 5e-324},
                    {"huge", 1.7976931348623157e308},
                    {"negative zero", -0.0},
                    {"third", 1.0 / 3.0},
                    {"big integer", 9007199254740993.0}};
    CHECK(metadata_to_json(m) == cereal_text(m));
    // A statistic JSON cannot hold is left out, as if it were not there.
    Metadata with_nan = m;
    with_nan.statistics["not a number"] = std::numeric_limits<double>::quiet_NaN();
    with_nan.statistics["infinite"] = -std::numeric_limits<double>::infinity();
    CHECK(metadata_to_json(with_nan) == cereal_text(m));
}
