# kdpm-bench and its optional peers (Embree 3, nanoflann): bench-only, never needed by the
# toolchain or runtime; each peer is compiled in when its Debian package is installed.
find_package(embree 3 QUIET)
find_path(NANOFLANN_INCLUDE_DIR nanoflann.hpp)

# kdpm_bench_peers: whichever peers are found (possibly none), for kdpm-bench and kdpm-bench-photons.
add_library(kdpm_bench_peers INTERFACE)
if(embree_FOUND)
  add_library(kdpm_peer_embree STATIC bench/peer_embree.cpp bench/peer_embree_photons.cpp)
  target_link_libraries(kdpm_peer_embree PUBLIC kdpm_backend_cpu kdpm_photon_shooter PRIVATE embree)
  target_link_libraries(kdpm_bench_peers INTERFACE kdpm_peer_embree)
  target_compile_definitions(kdpm_bench_peers INTERFACE KDPM_HAVE_EMBREE=1)
endif()
if(NANOFLANN_INCLUDE_DIR)
  add_library(kdpm_peer_nanoflann STATIC bench/peer_nanoflann.cpp)
  target_include_directories(kdpm_peer_nanoflann PRIVATE ${NANOFLANN_INCLUDE_DIR})
  target_link_libraries(kdpm_peer_nanoflann PUBLIC kdpm_backend_cpu)
  target_link_libraries(kdpm_bench_peers INTERFACE kdpm_peer_nanoflann)
  target_compile_definitions(kdpm_bench_peers INTERFACE KDPM_HAVE_NANOFLANN=1)
endif()
message(STATUS "kdpm-bench peers: Embree ${embree_FOUND}, nanoflann ${NANOFLANN_INCLUDE_DIR}")

kdpm_tool(kdpm-bench bench/bench_main.cpp
          kdpm_bench_peers kdpm_render kdpm_geometry_builder kdpm_photon_shooter kdpm_builders_photons)
target_sources(kdpm-bench PRIVATE bench/scene_bench.cpp bench/instance_bench.cpp bench/instance_report.cpp bench/bench_report.cpp bench/host_description.cpp)
# The full frame per mode, and the viewer's frame made as kdpm-view makes it (kdpm_view has no window).
target_sources(kdpm-bench PRIVATE bench/mode_frames.cpp bench/scenes_root.cpp)
target_link_libraries(kdpm-bench PRIVATE kdpm_view kdpm_runtime_photons)

# kdpm-bench-quality: error against time of every lighting mode against a path-traced reference.
kdpm_tool(kdpm-bench-quality bench/quality_main.cpp
          kdpm_render kdpm_geometry_builder kdpm_photon_shooter kdpm_builders_photons kdpm_runtime_photons)
target_sources(kdpm-bench-quality PRIVATE bench/quality_bench.cpp bench/quality_report.cpp bench/reference_cache.cpp
               bench/error_analysis.cpp
               bench/scenes_root.cpp render/pfm_reader.cpp)
