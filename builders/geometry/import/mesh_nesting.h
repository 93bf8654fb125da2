#pragma once
// Refuses meshes nested deeper than any real asset before Assimp sees them: its JSON (glTF),
// XML (COLLADA, ...) and node-hierarchy code recurses once per level, so a file of a few
// megabytes of "[[[[..." or of a 20,000-node chain would overflow any stack.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace kdpm {

inline constexpr std::size_t kMaxMeshNesting = 1000;

// Deepest nesting of JSON arrays/objects in `text` (strings skipped).
std::size_t json_nesting_depth(std::string_view text);
// Deepest nesting of XML elements in `text` (comments, CDATA, declarations and quoted attribute
// values skipped).
std::size_t xml_nesting_depth(std::string_view text);
// Longest parent-to-child chain of a glTF document's node hierarchy; a cycle counts as
// infinitely deep. 0 when the text is not a glTF document with nodes.
std::size_t gltf_node_depth(std::string_view json);

// Throws FormatError when a .gltf/.glb/.dae/.xml/... file nests deeper than kMaxMeshNesting.
void check_mesh_nesting(const std::filesystem::path& path);
// The same for bytes in memory; `extension` without or with its dot, `name` for messages.
void check_mesh_nesting(std::string_view bytes, const std::string& extension, const std::string& name);

}  // namespace kdpm
