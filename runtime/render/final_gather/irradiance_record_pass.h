#pragma once
// Makes irradiance cache records: at each given diffuse vertex, the final gather's rays over a
// stratified cosine-weighted hemisphere (M rows in sin^2 theta, N columns in phi, N ~ pi M,
// M N <= gather rays), giving the irradiance, the nearest hit's distance and Ward & Heckbert's
// rotational and translational gradients from the differences between neighbouring
// strata (translation: each stratum wall moves as the point moves, by 1 / (R sin theta) across
// a phi wall and cos theta / R across a theta wall; the nearer of the two hits is assumed).
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/render/final_gather/final_gather_pass.h"
#include "runtime/render/final_gather/irradiance_record.h"
#include "runtime/shading/constants.h"
#include "runtime/shading/diffuse.h"

namespace kdpm {

inline constexpr std::uint32_t kMaxRecordColumns = 512;

// Rows M and columns N of a record's strata for a number of gather rays.
KDPM_HD KDPM_INLINE void record_strata(std::uint32_t rays, std::uint32_t& rows, std::uint32_t& columns) {
    rows = static_cast<std::uint32_t>(sqrtf(static_cast<float>(rays) / kPi) + 0.5f);
    if (rows < 1) rows = 1;
    columns = rays / rows;
    if (columns < 1) columns = 1;
    if (columns > kMaxRecordColumns) columns = kMaxRecordColumns;
}

struct IrradianceRecordPass {
    FinalGatherPass gather;               // geometry, maps and estimate parameters, rays per record
    const std::uint64_t* slots = nullptr;  // vertex slots to make a record at
    IrradianceRecord* records = nullptr;   // one per slot
    float min_radius = 0.0f, max_radius = 1e30f;  // scene-wide clamp of R_i
    // The record's smallest R_i from the camera: a record then covers at least min_reach_pixels
    // of the image around it (Tabellion & Lamorlette 2004's minimum spacing), however near the
    // geometry. The footprint of a pixel at p is |p - eye| * pixel_spread (0: no such bound).
    glm::vec3 eye{0.0f};
    float pixel_spread = 0.0f;
    float min_reach_pixels = 0.0f;
    float accuracy = 1.0f;  // the cache's a: a record reaches a * R_i

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t slot = slots[item];
        const DiffuseVertex& v = gather.frame.vertices[slot];
        const std::uint64_t pixel = gather.frame.slot_pixel(slot);
        const std::uint32_t vertex = gather.frame.slot_vertex(slot);
        const std::uint64_t path = (pixel << 32) | gather.sample;
        std::uint32_t rows = 1, columns = 1;
        record_strata(gather.gather_rays, rows, columns);
        glm::vec3 t, b;
        tangent_frame(v.geometric_normal, t, b);  // as every gather ray (diffuse.h)
        KnnHeap heap;

        glm::vec3 previous_row_l[kMaxRecordColumns];
        float previous_row_d[kMaxRecordColumns];
        glm::vec3 sum(0.0f), rotation[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
        glm::vec3 translation[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
        float nearest_hit = std::numeric_limits<float>::infinity();
        const float m = static_cast<float>(rows), n = static_cast<float>(columns);
        float smallest = min_radius;
        if (pixel_spread > 0.0f) {
            const float footprint = glm::length(v.position - eye) * pixel_spread;
            const float r = min_reach_pixels * footprint / accuracy;
            if (r > smallest) smallest = r < max_radius ? r : max_radius;
        }
        // Hits closer than the smallest record radius would give gradients no record can use.
        auto at_least = [&](float d) { return d > smallest ? d : smallest; };
        auto add_difference = [&](const glm::vec3& axis, float coefficient, const glm::vec3& dl) {
            for (int c = 0; c < 3; ++c) translation[c] += axis * (coefficient * dl[c]);
        };
        for (std::uint32_t j = 0; j < rows; ++j) {
            glm::vec3 first_l(0.0f), left_l(0.0f);
            float first_d = 0.0f, left_d = 0.0f;
            for (std::uint32_t k = 0; k < columns; ++k) {
                const std::uint32_t ray = (vertex << 16) | (j * columns + k);
                const float u1 = counter_random(random_seed::gather, path, ray, 0);
                const float u2 = counter_random(random_seed::gather, path, ray, 1);
                const float sin2 = (static_cast<float>(j) + u1) / m;
                const float sin_t = sqrtf(sin2), cos_t = sqrtf(1.0f - sin2 > 1e-8f ? 1.0f - sin2 : 1e-8f);
                const float phi = 2.0f * kPi * (static_cast<float>(k) + u2) / n;
                const glm::vec3 dir =
                    glm::normalize(sin_t * cosf(phi) * t + sin_t * sinf(phi) * b + cos_t * v.geometric_normal);
                glm::vec3 l(0.0f);
                float d = std::numeric_limits<float>::infinity();
                // Exactly grazing: no light.
                if (glm::dot(dir, v.geometric_normal) > 0.0f) l = gather.follow(v, dir, path, ray, heap, d);
                sum += l;
                if (d > 0.0f && d < nearest_hit) nearest_hit = d;
                const glm::vec3 around = -sinf(phi) * t + cosf(phi) * b;
                for (int c = 0; c < 3; ++c) rotation[c] += around * (l[c] * sin_t / cos_t);
                if (j > 0) {
                    // The theta wall below this stratum, across the column's centre direction.
                    const float s = sqrtf(static_cast<float>(j) / m);
                    const float phi_c = 2.0f * kPi * (static_cast<float>(k) + 0.5f) / n;
                    const float nearest = at_least(d < previous_row_d[k] ? d : previous_row_d[k]);
                    add_difference(cosf(phi_c) * t + sinf(phi_c) * b,
                                   2.0f * kPi / n * s * (1.0f - s * s) / nearest, l - previous_row_l[k]);
                }
                if (k > 0) {
                    // The phi wall before this stratum.
                    const float wall = 2.0f * kPi * static_cast<float>(k) / n;
                    const float nearest = at_least(d < left_d ? d : left_d);
                    const float rise = sqrtf((static_cast<float>(j) + 1.0f) / m) - sqrtf(static_cast<float>(j) / m);
                    add_difference(-sinf(wall) * t + cosf(wall) * b, rise / nearest, l - left_l);
                } else {
                    first_l = l;
                    first_d = d;
                }
                if (k > 0) previous_row_l[k - 1] = left_l, previous_row_d[k - 1] = left_d;
                left_l = l;
                left_d = d;
            }
            if (columns > 1) {
                // The wall at phi = 0 between the last column and the first.
                const float nearest = at_least(first_d < left_d ? first_d : left_d);
                const float rise = sqrtf((static_cast<float>(j) + 1.0f) / m) - sqrtf(static_cast<float>(j) / m);
                add_difference(b, rise / nearest, first_l - left_l);
            }
            previous_row_l[columns - 1] = left_l;
            previous_row_d[columns - 1] = left_d;
        }
        const float cell = kPi / (m * n);  // the cosine-weighted solid angle of one stratum
        IrradianceRecord r;
        r.position = v.position;
        r.normal = v.geometric_normal;
        r.irradiance = sum * cell;
        for (int c = 0; c < 3; ++c) {
            r.rotation[c] = rotation[c] * cell;
            r.translation[c] = translation[c];
        }
        // The nearest hit, not Ward's harmonic mean: at a step's foot the step fills half the
        // hemisphere while the records beside the step see it in a few rays; the harmonic mean
        // of those rays is set by the room and lets such a record reach the foot.
        r.radius = nearest_hit < smallest ? smallest : (nearest_hit > max_radius ? max_radius : nearest_hit);
        records[item] = r;
    }
};

}  // namespace kdpm
