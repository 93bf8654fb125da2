# tools/view: kdpm-view, the interactive viewer (needs GLFW and OpenGL; skipped without them).
# The viewer library lives in runtime/view; it is added from here because this file is the
# viewer's own entry in the build.
add_subdirectory(${PROJECT_SOURCE_DIR}/runtime/view ${CMAKE_BINARY_DIR}/runtime/view)
if(TARGET glfw AND TARGET OpenGL::GL)
  kdpm_tool(kdpm-view view/view_main.cpp kdpm_view_window)
else()
  message(STATUS "kdpm: kdpm-view not built (GLFW 3 or OpenGL not found)")
endif()
