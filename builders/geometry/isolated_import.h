#pragma once
// Mesh import in a child process. Assimp can abort (its assertions are compiled in) or crash on
// hostile files in ways no check before it can foresee; in a child that is a one-line error of
// the tool instead of the end of it. The child sends the imported scene back through a pipe.
#include <filesystem>

#include "builders/geometry/scene.h"

namespace kdpm {

// import_mesh(path), run in a forked child. Throws FormatError with one line, also when the
// importer dies ("the importer crashed (Aborted)").
Scene import_mesh_isolated(const std::filesystem::path& path);

}  // namespace kdpm
