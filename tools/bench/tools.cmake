# tools/bench: executables of this area.
