#pragma once
// Copies of the scene's arrays in device memory: each mapped section goes up with one copy,
// straight from the mapped file, and the returned view points at the device copies (owned by
// `owned`, which must outlive the view). Used by the frame backend, photon shooting and the
// density view alike. Include from .cu files only.
#include <cstdint>
#include <vector>

#include "runtime/backend/device_buffer.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

template <class T>
const T* upload_array(std::vector<DeviceBuffer>& owned, const T* host, std::uint64_t count) {
    if (host == nullptr || count == 0) return nullptr;
    owned.push_back(DeviceBuffer::upload(host, count * sizeof(T)));
    return owned.back().as<const T>();
}

inline GeometryView upload_geometry(std::vector<DeviceBuffer>& owned, const GeometryView& h) {
    GeometryView d = h;
    // A scene of instances: each object's arrays, then the table of their device views, the
    // placements and the instance BVH (the scene has no triangles of its own).
    if (h.instance_count != 0) {
        std::vector<GeometryView> objects;
        objects.reserve(h.object_count);
        for (std::uint32_t i = 0; i < h.object_count; ++i) objects.push_back(upload_geometry(owned, h.objects[i]));
        d.objects = upload_array(owned, objects.data(), objects.size());
        d.instances = upload_array(owned, h.instances, h.instance_count);
        d.instance_nodes = upload_array(owned, h.instance_nodes, h.instance_node_count);
    }
    d.nodes = upload_array(owned, h.nodes, h.node_count);
    d.leaf_indices = upload_array(owned, h.leaf_indices, h.leaf_index_count);
    d.triangles = upload_array(owned, h.triangles, h.triangle_count);
    d.normals = upload_array(owned, h.normals, h.normals ? h.triangle_count : 0);
    d.materials = upload_array(owned, h.materials, h.material_count);
    d.lights = upload_array(owned, h.lights, h.light_count);
    d.uvs = upload_array(owned, h.uvs, h.uvs ? h.triangle_count : 0);
    d.textures = upload_array(owned, h.textures, h.texture_count);
    d.texels = upload_array(owned, h.texels, h.texel_count);
    // GPU threads walk the binary tree: the wide walk's stack (up to 449 entries a ray) does not
    // belong in a thread's local memory.
    d.wide = nullptr;
    d.wide_node_count = 0;
    return d;
}

inline PhotonMapView upload_photon_map(std::vector<DeviceBuffer>& owned, const PhotonMapView& h) {
    PhotonMapView d = h;
    d.nodes = upload_array(owned, h.nodes, h.node_count);
    d.x = upload_array(owned, h.x, h.photon_count);
    d.y = upload_array(owned, h.y, h.photon_count);
    d.z = upload_array(owned, h.z, h.photon_count);
    d.power = upload_array(owned, h.power, h.photon_count);
    d.directions = upload_array(owned, h.directions, h.photon_count);
    d.flags = upload_array(owned, h.flags, h.photon_count);
    // The CPU's decoded copies and node boxes are host memory: the device decodes per use and
    // scans every leaf it reaches.
    d.unpacked = nullptr;
    d.unpacked_power = nullptr;
    d.vector_bounds = nullptr;
    return d;
}

}  // namespace kdpm
