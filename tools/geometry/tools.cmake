# tools/geometry: executables of this area.
