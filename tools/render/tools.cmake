# tools/render: executables of this area.
kdpm_tool(kdpm-render render/render_main.cpp kdpm_cli_render)
kdpm_tool(kdpm-image-diff render/image_diff_main.cpp)
target_sources(kdpm-image-diff PRIVATE render/pfm_reader.cpp)
