#include "formats/metadata.h"

#include <cereal/archives/json.hpp>
#include <cereal/types/map.hpp>
#include <cereal/types/string.hpp>
#include <rapidjson/document.h>
#include <rapidjson/error/en.h>
#include <rapidjson/prettywriter.h>
#include <rapidjson/stringbuffer.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "formats/checksum.h"
#include "formats/format_error.h"

namespace kdpm {

namespace {

// String-keyed maps as JSON objects ({"max_depth": "40"}), so metadata reads naturally in
// kdpm-inspect --json; cereal's default would be a list of key/value pairs.
template <class T>
void load_object(cereal::JSONInputArchive& ar, const char* name, std::map<std::string, T>& map) {
    ar.setNextName(name);
    ar.startNode();
    while (const char* key = ar.getNodeName()) {
        T value{};
        std::string k = key;
        ar(value);
        map.emplace(std::move(k), std::move(value));
    }
    ar.finishNode();
}

}  // namespace

template <class Archive>
void load(Archive& ar, Metadata& m) {
    ar(cereal::make_nvp("tool", m.tool), cereal::make_nvp("tool_version", m.tool_version),
       cereal::make_nvp("source_path", m.source_path), cereal::make_nvp("source_hash", m.source_hash));
    load_object(ar, "parameters", m.parameters);
    load_object(ar, "statistics", m.statistics);
}

std::string metadata_to_json(const Metadata& m) {
    // RapidJSON's pretty writer straight into a string buffer, as cereal's JSON archive would set
    // it up (4-space indent, its default precision), so the text is the same byte for byte: the
    // archive feeds an std::ostream a character at a time, which costs a large share of building
    // a small scene's .kdg.
    rapidjson::StringBuffer buffer;
    rapidjson::PrettyWriter<rapidjson::StringBuffer> w(buffer);
    w.SetIndent(' ', 4);
    const auto text = [&](const std::string& s) { w.String(s.data(), static_cast<rapidjson::SizeType>(s.size())); };
    w.StartObject();
    w.Key("kdpm");
    w.StartObject();
    for (const auto& [key, value] : {std::pair{"tool", &m.tool}, std::pair{"tool_version", &m.tool_version},
                                     std::pair{"source_path", &m.source_path}, std::pair{"source_hash", &m.source_hash}}) {
        w.Key(key);
        text(*value);
    }
    w.Key("parameters");
    w.StartObject();
    for (const auto& [key, value] : m.parameters) text(key), text(value);
    w.EndObject();
    w.Key("statistics");
    w.StartObject();
    // JSON has no NaN or infinity (the writer would refuse them): such a statistic carries no
    // information and is left out, so the text stays valid JSON.
    for (const auto& [key, value] : m.statistics)
        if (std::isfinite(value)) text(key), w.Double(value);
    w.EndObject();
    w.EndObject();
    w.EndObject();
    return std::string(buffer.GetString(), buffer.GetSize());
}

namespace {

// RapidJSON parses recursively: refuse deep nesting before it sees the text, so a hostile file
// cannot exhaust the stack. kdpm's own metadata nests three levels.
bool nesting_within(std::string_view json, int max_depth) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        char c = json[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            if (++depth > max_depth) return false;
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return true;
}

// The shape cereal expects, checked first so that garbage gets a reason instead of a parser
// assertion: {"kdpm": {"tool": "", "tool_version": "", "source_path": "", "source_hash": "",
// "parameters": {"name": ""}, "statistics": {"name": 0}}}. Empty when the shape is right.
std::string metadata_shape_error(std::string_view json) {
    rapidjson::Document doc;
    doc.Parse<rapidjson::kParseIterativeFlag>(json.data(), json.size());
    if (doc.HasParseError()) return std::string("not JSON (") + rapidjson::GetParseError_En(doc.GetParseError()) + ")";
    if (!doc.IsObject() || !doc.HasMember("kdpm") || !doc["kdpm"].IsObject()) return "no \"kdpm\" object";
    const auto& k = doc["kdpm"];
    for (const char* key : {"tool", "tool_version", "source_path", "source_hash"})
        if (!k.HasMember(key) || !k[key].IsString()) return std::string("\"") + key + "\" is missing or not a string";
    if (!k.HasMember("parameters") || !k["parameters"].IsObject()) return "\"parameters\" is missing or not an object";
    for (const auto& p : k["parameters"].GetObject())
        if (!p.value.IsString()) return std::string("parameter \"") + p.name.GetString() + "\" is not a string";
    if (!k.HasMember("statistics") || !k["statistics"].IsObject()) return "\"statistics\" is missing or not an object";
    for (const auto& p : k["statistics"].GetObject())
        if (!p.value.IsNumber()) return std::string("statistic \"") + p.name.GetString() + "\" is not a number";
    return {};
}

}  // namespace

Metadata metadata_from_json(std::string_view json) {
    if (json.size() > (1u << 24) || !nesting_within(json, 8))
        throw FormatError("metadata section is not valid kdpm JSON: too large or too deeply nested");
    if (const std::string why = metadata_shape_error(json); !why.empty())
        throw FormatError("metadata section is not valid kdpm JSON: " + why);
    Metadata m;
    try {
        std::istringstream in{std::string(json)};
        cereal::JSONInputArchive ar(in);
        ar(cereal::make_nvp("kdpm", m));
    } catch (const std::exception& e) {
        throw FormatError(std::string("metadata section is not valid kdpm JSON: ") + e.what());
    }
    return m;
}

std::string hash_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FormatError("cannot read '" + path + "'");
    // Read in large blocks: an istreambuf_iterator costs several instructions a byte, which adds up
    // when a large .kdg is hashed for the photon file's metadata.
    // A regular file comes in one read (its size and one byte more, to meet the end).
    std::error_code size_error;
    const auto size = std::filesystem::file_size(path, size_error);
    const std::size_t block = size_error ? std::size_t{1} << 16 : static_cast<std::size_t>(size) + 1;
    std::vector<char> bytes;
    for (;;) {
        const std::size_t old = bytes.size();
        bytes.resize(old + block);
        in.read(bytes.data() + old, static_cast<std::streamsize>(block));
        bytes.resize(old + static_cast<std::size_t>(in.gcount()));
        if (!in) break;
    }
    if (in.bad()) throw FormatError("cannot read '" + path + "'");
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(checksum64(bytes.data(), bytes.size())));
    return hex;
}

const char* kdpm_version() { return KDPM_VERSION; }

}  // namespace kdpm
