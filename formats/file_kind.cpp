#include "formats/file_kind.h"

#include <cstring>

namespace kdpm {
namespace {

const FileKindInfo kKinds[] = {
    {FileKind::geometry, {'K', 'D', 'P', 'M', '-', 'G', 'E', 'O'}, 1, 3, "geometry kd-tree", ".kdg",
     "kdpm-build-geometry SCENE -o FILE.kdg"},
    {FileKind::photon_hits, {'K', 'D', 'P', 'M', '-', 'P', 'H', 'H'}, 1, 0, "photon hits", ".kdph",
     "kdpm-shoot-photons SCENE.kdg -o FILE.kdph"},
    {FileKind::photon_tree, {'K', 'D', 'P', 'M', '-', 'P', 'H', 'T'}, 1, 1, "photon kd-tree", ".kdp",
     "kdpm-build-photons PHOTONS.kdph -o FILE.kdp"},
    {FileKind::test, {'K', 'D', 'P', 'M', '-', 'T', 'S', 'T'}, 1, 0, "test container", ".kdt",
     "the test that wrote it"},
};

}  // namespace

const FileKindInfo& file_kind_info(FileKind kind) { return kKinds[static_cast<int>(kind)]; }

std::optional<FileKind> file_kind_from_magic(const char (&magic)[8]) {
    for (const auto& k : kKinds)
        if (std::memcmp(k.magic, magic, 8) == 0) return k.kind;
    return std::nullopt;
}

}  // namespace kdpm
