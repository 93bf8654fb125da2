#pragma once
// A photon kd-tree file (.kdp) mapped read-only and checked once on open like every kdpm file the
// runtime loads (section checksums, then the tree invariants), exposing each photon map as a
// PhotonMapView over the mapping.
#include <filesystem>

#include "formats/container_reader.h"
#include "formats/metadata.h"
#include "formats/photon_layout.h"
#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

class PhotonMapFile {
public:
    // Throws FormatError with a one-line reason (missing, wrong kind or version, corrupt).
    static PhotonMapFile open(const std::filesystem::path& path);
    // Over a copy of the bytes (tests).
    static PhotonMapFile from_bytes(std::span<const std::uint8_t> bytes, std::string name);

    bool has_map(PhotonMapKind map) const;
    // An empty view (node_count 0) when the map is absent.
    PhotonMapView view(PhotonMapKind map = PhotonMapKind::global) const;
    // The precomputed irradiance (format 1.1); not present() in files without it.
    IrradianceMapView irradiance_map() const;
    // A zeroed info when the map is absent.
    PhotonTreeInfo info(PhotonMapKind map = PhotonMapKind::global) const;
    Metadata metadata() const { return reader_.metadata(); }
    const ContainerReader& container() const { return reader_; }

private:
    explicit PhotonMapFile(ContainerReader reader);
    ContainerReader reader_;
};

}  // namespace kdpm
