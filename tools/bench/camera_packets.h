#pragma once
// One frame's camera rays as the renderer's CPU backend traces them: 16-ray packets of 4x4
// pixels (CameraPacketPass, launched as CpuDevice launches it), hits per pixel, row-major.
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/render/camera.h"
#include "runtime/render/passes/camera_packet_pass.h"
#include "tools/bench/median_time.h"

namespace kdpm::bench {

// Wall time of one pass (ms).
inline double trace_camera_packets(const GeometryView& g, const PinholeCamera& camera, std::vector<Hit>& hits) {
    hits.resize(static_cast<std::size_t>(camera.width) * camera.height);
    return median_ms(1, [&] {
        cpu_parallel_for(CameraPacketPass::work_items(camera.width, camera.height),
                         CameraPacketPass{g, camera, 0, hits.data()}, 16);
    });
}

}  // namespace kdpm::bench
