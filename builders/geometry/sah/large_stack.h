#pragma once
// Runs a function on a thread with a large stack. Assimp's importers recurse once per nesting
// level of a file (JSON arrays, XML elements, node hierarchies); on the main thread's 8 MiB a
// hostile file overflows the stack, on this one the importer has room for any file that
// passes the nesting pre-check (mesh_nesting.h).
#include <cstddef>
#include <functional>

namespace kdpm {

inline constexpr std::size_t kImportStackBytes = std::size_t{1} << 30;  // reserved, touched only as used

// Runs `fn` to completion on its own thread; rethrows what it throws.
void run_with_large_stack(const std::function<void()>& fn, std::size_t stack_bytes = kImportStackBytes);

}  // namespace kdpm
