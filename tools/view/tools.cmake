# tools/view: kdpm-view, the interactive viewer (needs GLFW and OpenGL; skipped without them).
if(TARGET kdpm_view_window)
  kdpm_tool(kdpm-view view/view_main.cpp kdpm_cli_render kdpm_view_window)
else()
  message(STATUS "kdpm: kdpm-view not built (GLFW 3, OpenGL or Dear ImGui not found)")
endif()
