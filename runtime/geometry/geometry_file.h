#pragma once
// A .kdg file opened for rendering: memory-mapped (no copy), checked once on open like every
// kdpm file the runtime loads (section checksums, required sections, record sizes, every index
// in range, tree shape and depth), then exposed as a GeometryView that kernels can use directly.
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "formats/container_reader.h"
#include "formats/geometry_layout.h"
#include "runtime/geometry/geometry_view.h"

namespace kdpm {

class GeometryFile {
public:
    // Throws FormatError with a one-line reason for a missing, corrupt or foreign file. A scene of
    // instances (format 1.3) opens its object files too, relative to its own folder, and refuses
    // one whose content hash is not the one it was built with.
    static GeometryFile open(const std::filesystem::path& path);
    // Over a copy of the caller's bytes (tests); object paths are taken relative to `folder`.
    static GeometryFile from_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                                   const std::filesystem::path& folder = {});
    GeometryFile(GeometryFile&&) noexcept;
    GeometryFile& operator=(GeometryFile&&) noexcept;
    ~GeometryFile();

    // The content hash a scene of instances stores for this file: its section table's checksum,
    // which covers every section's checksum.
    std::uint64_t content_hash() const;
    bool has_instances() const { return instances_ != nullptr; }

    const GeometryView& view() const { return view_; }
    const GeometryInfo& info() const { return view_.info; }
    const CameraRecord& camera() const { return camera_; }
    Metadata metadata() const { return reader_.metadata(); }
    const ContainerReader& reader() const { return reader_; }

    std::span<const TriangleRecord> triangles() const { return {view_.triangles, view_.triangle_count}; }
    std::span<const MaterialRecord> materials() const { return {view_.materials, view_.material_count}; }
    std::span<const AreaLightRecord> lights() const { return {view_.lights, view_.light_count}; }

private:
    GeometryFile(ContainerReader reader, const std::filesystem::path& folder);
    void open_instances(const std::filesystem::path& folder);
    struct Instances;  // the objects' files and views, placements, instance BVH, world lights
    ContainerReader reader_;
    std::unique_ptr<Instances> instances_;
    GeometryView view_{};
    CameraRecord camera_{};
};

}  // namespace kdpm
