#pragma once
// Small scenes assembled in memory for renderer tests: quads of two triangles, materials and
// card lights, under a one-leaf kd-tree (every ray tests every triangle, so the tree is trivially
// right and the tests exercise only the renderer).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "formats/geometry_layout.h"
#include "formats/kd_node.h"
#include "runtime/render/scene_views.h"

namespace kdpm::test {

class HandBuiltScene {
public:
    std::uint32_t add_material(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f),
                               MaterialKind kind = MaterialKind::diffuse) {
        MaterialRecord m{};
        set(m.diffuse, albedo);
        set(m.emission, emission);
        set(m.specular, glm::vec3(1.0f));
        set(m.transmission, glm::vec3(1.0f));
        m.ior = 1.5f;
        m.kind = static_cast<std::uint32_t>(kind);
        materials.push_back(m);
        return static_cast<std::uint32_t>(materials.size() - 1);
    }
    // Two triangles p0 + [0,1]e1 + [0,1]e2, front side along cross(e1, e2).
    void add_quad(glm::vec3 p0, glm::vec3 e1, glm::vec3 e2, std::uint32_t material) {
        add_triangle(p0, e1, e2, material);
        add_triangle(p0 + e1 + e2, -e1, -e2, material);
    }
    void add_triangle(glm::vec3 v0, glm::vec3 e1, glm::vec3 e2, std::uint32_t material) {
        TriangleRecord t{};
        set(t.v0, v0);
        set(t.e1, e1);
        set(t.e2, e2);
        t.material = material;
        t.source_index = static_cast<std::uint32_t>(triangles.size());
        triangles.push_back(t);
    }
    // A light that is not scene geometry (like a scene card's light).
    void add_parallelogram_light(glm::vec3 p0, glm::vec3 e1, glm::vec3 e2, glm::vec3 radiance) {
        AreaLightRecord l{};
        set(l.p0, p0);
        set(l.e1, e1);
        set(l.e2, e2);
        set(l.radiance, radiance);
        l.shape = static_cast<std::uint32_t>(LightShape::parallelogram);
        l.triangle = 0xffffffffu;
        l.area = glm::length(glm::cross(e1, e2));
        l.power = 3.14159265f * l.area * (radiance.x + radiance.y + radiance.z) / 3.0f;
        lights.push_back(l);
    }
    void set_camera(glm::vec3 eye, glm::vec3 lookat, glm::vec3 up, float vfov, std::uint32_t w, std::uint32_t h) {
        set(camera.eye, eye);
        set(camera.lookat, lookat);
        set(camera.up, up);
        camera.vfov_degrees = vfov;
        camera.width = w;
        camera.height = h;
    }

    // Views into this object: keep it alive (and unchanged) while they are used.
    SceneViews views() {
        nodes = {KdNode::leaf(0, static_cast<std::uint32_t>(triangles.size()))};
        leaf_indices.resize(triangles.size());
        for (std::uint32_t i = 0; i < leaf_indices.size(); ++i) leaf_indices[i] = i;
        GeometryInfo info{};
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const auto& t : triangles) {
            glm::vec3 v0(t.v0[0], t.v0[1], t.v0[2]), e1(t.e1[0], t.e1[1], t.e1[2]), e2(t.e2[0], t.e2[1], t.e2[2]);
            for (glm::vec3 p : {v0, v0 + e1, v0 + e2}) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        }
        set(info.bounds_min, lo);
        set(info.bounds_max, hi);
        info.triangle_count = static_cast<std::uint32_t>(triangles.size());
        info.node_count = 1;
        info.leaf_index_count = info.triangle_count;
        info.default_k = 50;
        SceneViews v;
        v.geometry.nodes = nodes.data();
        v.geometry.node_count = 1;
        v.geometry.leaf_indices = leaf_indices.data();
        v.geometry.leaf_index_count = info.leaf_index_count;
        v.geometry.triangles = triangles.data();
        v.geometry.triangle_count = info.triangle_count;
        v.geometry.materials = materials.data();
        v.geometry.material_count = static_cast<std::uint32_t>(materials.size());
        v.geometry.lights = lights.data();
        v.geometry.light_count = static_cast<std::uint32_t>(lights.size());
        v.geometry.info = info;
        v.camera = camera;
        return v;
    }

    std::vector<TriangleRecord> triangles;
    std::vector<MaterialRecord> materials;
    std::vector<AreaLightRecord> lights;
    std::vector<KdNode> nodes;
    std::vector<std::uint32_t> leaf_indices;
    CameraRecord camera{};

private:
    static void set(float (&out)[3], glm::vec3 v) {
        out[0] = v.x;
        out[1] = v.y;
        out[2] = v.z;
    }
};

}  // namespace kdpm::test
