# tools/render: executables of this area.
