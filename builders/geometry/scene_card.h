#pragma once
// Scene cards: a small JSON file next to (or pointing at) a mesh that adds what mesh formats do
// not carry: camera, extra area lights, rendering defaults and the up axis.
//
// {
//   "mesh": "cornell-box.obj",                     // relative to the card
//   "shared_scene": "sponza/sponza.obj",           // optional: used under $KDPM_SCENES when set
//   "up": "y",                                     // x, y or z (default y)
//   "camera": { "eye": [0,1,3.9], "lookat": [0,1,0], "up": [0,1,0], "vfov": 40,
//               "width": 512, "height": 512 },     // optional: framed from the bounds when absent
//   "lights": [ { "p0": [..], "e1": [..], "e2": [..], "radiance": [..] } ],  // optional
//   "photons": 262144, "bounces": 4, "k": 64       // optional
// }
#include <filesystem>
#include <vector>

#include "builders/geometry/scene.h"
#include "formats/instance_layout.h"

namespace kdpm {

// True for inputs that are scene cards (*.json), false for meshes.
bool is_scene_card(const std::filesystem::path& input);

// The mesh a card names, resolved ($KDPM_SCENES first when the card has "shared_scene").
std::filesystem::path card_mesh_path(const std::filesystem::path& card);

// Applies a card's text (its up axis, defaults, lights and camera; not its mesh) to an imported
// scene. Throws FormatError with one line. load_scene_input's second half, and the fuzzer's entry.
void apply_scene_card(const std::string& json, const std::string& name, Scene& scene);

// Cards of instances place object .kdg files instead of naming a mesh (format 1.3):
//   "instances": [ { "object": "sponza.kdg",                        // relative to the card
//                    "translate": [x,y,z], "rotate": {"axis": [x,y,z], "degrees": d},
//                    "scale": s or [sx,sy,sz],                       // T * R * S; or "matrix": 12 numbers
//                    "repeat": {"count": [nx,ny,nz], "step": [x,y,z]} } ]   // optional: a grid of copies
struct InstanceCard {
    std::vector<std::filesystem::path> objects;  // distinct object files, in order of first use
    std::vector<InstanceRecord> instances;       // object indexes into `objects`
    Scene settings;                              // the card's lights, camera, defaults; no triangles
    bool card_camera = false;                    // false: frame the camera on the placed objects
};

bool card_places_instances(const std::filesystem::path& card);
// Throws FormatError with one line.
InstanceCard read_instance_card(const std::filesystem::path& card);

// Card or bare mesh -> complete scene (camera always set). Throws FormatError with one line.
Scene load_scene_input(const std::filesystem::path& input);

}  // namespace kdpm
