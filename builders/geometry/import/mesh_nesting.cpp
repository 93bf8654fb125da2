#include "builders/geometry/import/mesh_nesting.h"

#include <rapidjson/document.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "formats/format_error.h"

namespace kdpm {

std::size_t json_nesting_depth(std::string_view text) {
    std::size_t depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

std::size_t xml_nesting_depth(std::string_view text) {
    std::size_t depth = 0, deepest = 0;
    auto skip_past = [&](std::size_t from, std::string_view end) {
        const std::size_t at = text.find(end, from);
        return at == std::string_view::npos ? text.size() : at + end.size();
    };
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] != '<') {
            ++i;
            continue;
        }
        if (text.compare(i, 4, "<!--") == 0) {
            i = skip_past(i + 4, "-->");
        } else if (text.compare(i, 9, "<![CDATA[") == 0) {
            i = skip_past(i + 9, "]]>");
        } else if (i + 1 < text.size() && (text[i + 1] == '?' || text[i + 1] == '!')) {
            i = skip_past(i + 2, ">");
        } else if (i + 1 < text.size() && text[i + 1] == '/') {
            if (depth > 0) --depth;
            i = skip_past(i + 2, ">");
        } else {
            // An opening tag; quoted attribute values may hold '>' or "/>".
            char quote = 0;
            std::size_t j = i + 1;
            for (; j < text.size(); ++j) {
                if (quote) {
                    if (text[j] == quote) quote = 0;
                } else if (text[j] == '"' || text[j] == '\'') {
                    quote = text[j];
                } else if (text[j] == '>') {
                    break;
                }
            }
            const bool self_closing = j < text.size() && j > i + 1 && text[j - 1] == '/';
            if (!self_closing) deepest = std::max(deepest, ++depth);
            i = j + 1;
        }
    }
    return deepest;
}

std::size_t gltf_node_depth(std::string_view json) {
    rapidjson::Document doc;
    doc.Parse<rapidjson::kParseIterativeFlag>(json.data(), json.size());
    if (doc.HasParseError() || !doc.IsObject() || !doc.HasMember("nodes") || !doc["nodes"].IsArray()) return 0;
    const auto& nodes = doc["nodes"];
    const std::size_t n = nodes.Size();
    std::vector<std::vector<std::size_t>> children(n);
    for (rapidjson::SizeType i = 0; i < n; ++i) {
        if (!nodes[i].IsObject() || !nodes[i].HasMember("children") || !nodes[i]["children"].IsArray()) continue;
        for (const auto& c : nodes[i]["children"].GetArray())
            if (c.IsUint() && c.GetUint() < n) children[i].push_back(c.GetUint());
    }
    // Longest chain below each node, by an iterative depth-first walk; a node met again while
    // still on the walk's path closes a cycle.
    enum : std::uint8_t { unseen, on_path, done };
    std::vector<std::uint8_t> state(n, unseen);
    std::vector<std::size_t> height(n, 1);
    std::size_t deepest = 0;
    for (std::size_t root = 0; root < n; ++root) {
        if (state[root] != unseen) continue;
        std::vector<std::pair<std::size_t, std::size_t>> path{{root, 0}};  // node, next child
        state[root] = on_path;
        while (!path.empty()) {
            auto& [node, next] = path.back();
            if (next < children[node].size()) {
                const std::size_t child = children[node][next++];
                if (state[child] == on_path) return std::numeric_limits<std::size_t>::max();
                if (state[child] == unseen) {
                    state[child] = on_path;
                    path.push_back({child, 0});
                }
                continue;
            }
            for (std::size_t c : children[node]) height[node] = std::max(height[node], height[c] + 1);
            state[node] = done;
            deepest = std::max(deepest, height[node]);
            path.pop_back();
        }
    }
    return deepest;
}

namespace {

std::string lower_extension(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string read_all(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool is_json_mesh(const std::string& ext) { return ext == ".gltf" || ext == ".glb"; }

// Formats Assimp reads with its recursive XML parser.
bool is_xml_mesh(const std::string& ext) {
    for (const char* e : {".dae", ".xml", ".x3d", ".xgl", ".zgl", ".amf", ".irr", ".irrmesh", ".ogex", ".mesh"})
        if (ext == e) return true;
    return false;
}

// The JSON chunk of a binary glTF: 12-byte header, then chunk length, chunk type "JSON".
std::string_view glb_json(std::string_view bytes) {
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

}  // namespace

void check_mesh_nesting(std::string_view bytes, const std::string& extension, const std::string& name) {
    std::string ext = extension;
    if (!ext.empty() && ext[0] != '.') ext.insert(ext.begin(), '.');
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool json = is_json_mesh(ext), xml = is_xml_mesh(ext);
    auto refuse = [&](const char* what, std::size_t depth) {
        if (depth == std::numeric_limits<std::size_t>::max()) throw FormatError(name + ": " + what + " has a cycle");
        throw FormatError(name + ": " + what + " is nested " + std::to_string(depth) + " levels deep (at most " +
                          std::to_string(kMaxMeshNesting) + " are accepted)");
    };
    if (json) {
        const std::string_view text = ext == ".glb" ? glb_json(bytes) : bytes;
        if (const std::size_t d = json_nesting_depth(text); d > kMaxMeshNesting) refuse("JSON", d);
        if (const std::size_t d = gltf_node_depth(text); d > kMaxMeshNesting) refuse("the node hierarchy", d);
    } else if (xml) {
        if (const std::size_t d = xml_nesting_depth(bytes); d > kMaxMeshNesting) refuse("XML", d);
    }
}

void check_mesh_nesting(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (is_json_mesh(ext) || is_xml_mesh(ext)) check_mesh_nesting(read_all(path), ext, path.string());
}

}  // namespace kdpm
