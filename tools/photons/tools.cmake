# tools/photons: executables of this area.
