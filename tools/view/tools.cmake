# tools/view: executables of this area.
