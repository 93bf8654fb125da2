# `cmake --install build --prefix P`: the executables (tools/), the libraries with their headers,
# and a CMake package so that another program's `find_package(kdpm)` gives
#   kdpm::formats  read, write and validate kdpm files (no Assimp)
#   kdpm::runtime  map .kdg/.kdp, trace rays, gather photons, render a frame
include(CMakePackageConfigHelpers)

# The runtime as one name for users; the static libraries behind it are exported with it.
add_library(kdpm_runtime INTERFACE)
target_link_libraries(kdpm_runtime INTERFACE kdpm_render kdpm_photon_shooter)
set_target_properties(kdpm_formats PROPERTIES EXPORT_NAME formats)
set_target_properties(kdpm_runtime PROPERTIES EXPORT_NAME runtime)

set(kdpm_exported kdpm_formats kdpm_runtime kdpm_render kdpm_photon_shooter kdpm_backend kdpm_backend_cpu
    kdpm_geometry_runtime kdpm_runtime_photons kdpm_shading)
if(TARGET kdpm_oiio_loader)
  list(APPEND kdpm_exported kdpm_oiio_loader)
endif()
if(TARGET kdpm_cudart)
  list(APPEND kdpm_exported kdpm_cudart)
endif()
install(TARGETS ${kdpm_exported} EXPORT kdpm-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT kdpm-targets NAMESPACE kdpm:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kdpm)

install(DIRECTORY formats/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/kdpm/formats FILES_MATCHING PATTERN "*.h")
# The viewer needs GLFW and a window; it is an executable, not part of the library.
install(DIRECTORY runtime/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/kdpm/runtime
        FILES_MATCHING PATTERN "*.h" PATTERN "*.inc" PATTERN "*.cuh" PATTERN "view" EXCLUDE)
# kdpm-bench finds its scene cards under share/kdpm when run from an installed prefix.
install(DIRECTORY scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/kdpm)

configure_package_config_file(cmake/kdpm-config.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/kdpm-config.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kdpm)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/kdpm-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/kdpm-config.cmake ${CMAKE_CURRENT_BINARY_DIR}/kdpm-config-version.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kdpm)
