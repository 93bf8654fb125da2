# tools/geometry: executables of this area.
kdpm_tool(kdpm-build-geometry geometry/build_geometry_main.cpp kdpm_jobs)
kdpm_tool(kdpm-bench-build geometry/bench_build_main.cpp kdpm_geometry_builder kdpm_backend_cpu)
target_compile_definitions(kdpm-bench-build PRIVATE KDPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# kdpm-bench-rays: the binary and the wide walk on the same rays.
kdpm_tool(kdpm-bench-rays geometry/bench_rays_main.cpp kdpm_geometry_builder kdpm_render kdpm_backend_cpu)
target_compile_definitions(kdpm-bench-rays PRIVATE KDPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
