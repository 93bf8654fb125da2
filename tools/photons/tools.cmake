# tools/photons: executables of this area.
kdpm_tool(kdpm-build-photons photons/build_photons_main.cpp kdpm_jobs)
kdpm_tool(kdpm-merge-photons photons/merge_photons_main.cpp kdpm_builders_photons)
kdpm_tool(kdpm-shoot-photons photons/shoot_photons_main.cpp kdpm_jobs)
# nanoflann comes with kdpm_bench_peers (tools/bench/tools.cmake) when its headers are installed.
kdpm_tool(kdpm-bench-photons photons/bench_photons_main.cpp kdpm_photon_shooter kdpm_builders_photons
  kdpm_runtime_photons kdpm_geometry_builder kdpm_backend_cpu kdpm_bench_peers)
target_sources(kdpm-bench-photons PRIVATE photons/primary_hits.cpp)
target_compile_definitions(kdpm-bench-photons PRIVATE KDPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
