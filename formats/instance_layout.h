#pragma once
// The instance sections of a .kdg (format 1.3): a scene that places other .kdg files, its
// objects, in the world by affine transforms. Each object is built once, by kdpm-build-geometry
// like any scene, and read in place by every scene that places it; the scene file stores only
// where each object file is and its content hash, so a rebuilt object is noticed, not misread.
#include <cstdint>

namespace kdpm {

inline constexpr std::uint32_t kObjectPathBytes = 240;

// geometry.objects: one object file.
struct ObjectReference {
    char path[kObjectPathBytes];    // UTF-8, NUL-terminated, relative to the scene file's folder
    std::uint64_t content_hash;     // the object file's section_table_checksum when the scene was built
    std::uint32_t triangle_count;   // the object's, for kdpm-inspect without opening it
    std::uint32_t reserved;
};
static_assert(sizeof(ObjectReference) == 256);

// geometry.instances: one placement of an object. World point = M * (object point, 1), with M
// the 3x4 row-major `world_from_object`.
struct InstanceRecord {
    float world_from_object[12];
    std::uint32_t object;           // index into geometry.objects
    std::uint32_t reserved[3];
};
static_assert(sizeof(InstanceRecord) == 64);

// Most instances a scene may place: the runtime's instance indices stay far below kNoHit.
inline constexpr std::uint32_t kMaxInstances = 1u << 24;

}  // namespace kdpm
