# tools/photons: executables of this area.
kdpm_tool(kdpm-build-photons photons/build_photons_main.cpp kdpm_builders_photons kdpm_backend_cpu)
kdpm_tool(kdpm-shoot-photons photons/shoot_photons_main.cpp kdpm_photon_shooter kdpm_builders_photons kdpm_backend_cpu)
