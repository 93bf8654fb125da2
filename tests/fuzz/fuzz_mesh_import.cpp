// Feeds arbitrary bytes to the mesh importer as kdpm-build-geometry runs it: kdpm's checks here,
// Assimp in a forked child (Assimp crashes on some hostile files; kdpm's contract is that this is
// a one-line error, not the end of the tool). The first byte picks the format, the rest is the
// file. A crash, hang or sanitizer report of this process is a bug; a child still busy after
// 5 s is stopped (an Assimp loop, reported as an error like its crashes). KDPM_FUZZ_SEED=DIR writes one small seed per format and exits.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "builders/geometry/import/isolated_import.h"
#include "formats/format_error.h"

namespace {

const char* const kFormats[] = {"obj", "ply", "gltf", "dae", "stl", "off"};
constexpr std::size_t kFormatCount = sizeof kFormats / sizeof kFormats[0];

const char* const kSeeds[kFormatCount] = {
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
    R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
    R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
    R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
    R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})",
    R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">)"
    R"(<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0)"
    R"(</float_array><technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>)"
    R"(<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>)"
    R"(<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1">)"
    R"(<input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry>)"
    R"(</library_geometries><library_visual_scenes><visual_scene id="s"><node><instance_geometry url="#g"/>)"
    R"(</node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)",
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n",
    "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* dir = std::getenv("KDPM_FUZZ_SEED")) {
        for (std::size_t i = 0; i < kFormatCount; ++i)
            std::ofstream(std::string(dir) + "/seed." + kFormats[i], std::ios::binary)
                << static_cast<char>(i) << kSeeds[i];
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        (void)kdpm::import_mesh_from_memory_isolated(bytes, kFormats[data[0] % kFormatCount], "fuzz", 5);
    } catch (const kdpm::FormatError&) {
    }
    return 0;
}
