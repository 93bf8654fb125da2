#pragma once
// Mesh import in a child process. Assimp can abort (its assertions are compiled in) or crash on
// hostile files in ways no check before it can foresee; in a child that is a one-line error of
// the tool instead of the end of it. The child sends the imported scene back through a pipe.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "builders/geometry/scene.h"

namespace kdpm {

// Runs `import` in a forked child and returns its scene; `what` names the input in messages.
// A child that dies (Assimp's aborts and crashes), fails, or outlives `time_limit_s` (0: no limit)
// is a one-line FormatError here; an exception in the child is rethrown with its message.
Scene run_isolated(const std::function<Scene()>& import, const std::string& what, unsigned time_limit_s);

// import_mesh(path), run in a forked child. Throws FormatError with one line, also when the
// importer dies ("the importer crashed (Aborted)").
Scene import_mesh_isolated(const std::filesystem::path& path);

// import_mesh_from_memory, the same way; a child still busy after `time_limit_s` seconds (0: no
// limit) is killed and reported as such.
Scene import_mesh_from_memory_isolated(std::string_view bytes, const std::string& extension, const std::string& name,
                                       unsigned time_limit_s = 0);

}  // namespace kdpm
