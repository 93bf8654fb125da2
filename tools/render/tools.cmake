# tools/render: executables of this area.
kdpm_tool(kdpm-render render/render_main.cpp kdpm_render)
