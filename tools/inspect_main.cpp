// kdpm-inspect FILE: what is this kdpm file, what does it hold, and what made it.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "formats/container_reader.h"
#include "formats/instance_layout.h"
#include "formats/section_ids.h"
#include "tools/cli/args.h"
#include "tools/cli/json_text.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

namespace {

const char* type_name(std::uint32_t t) {
    switch (static_cast<ElementType>(t)) {
        case ElementType::bytes: return "bytes";
        case ElementType::u32: return "u32";
        case ElementType::i32: return "i32";
        case ElementType::f32: return "f32";
        case ElementType::u64: return "u64";
        case ElementType::f64: return "f64";
        case ElementType::record: return "record";
        case ElementType::text: return "text";
    }
    return "unknown";
}

std::string hex(std::uint64_t v) {
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
    return b;
}

// The objects a scene of instances places, each with its state now: "current" (its content hash
// is the one the scene was built with), "changed since the scene was built", or why it cannot be
// read. Only headers are read: kdpm-validate checks the objects in full.
struct ObjectState {
    std::string path;
    std::uint64_t hash;
    std::uint32_t triangles;
    std::string state;
};

std::vector<ObjectState> object_states(const ContainerReader& r, const std::filesystem::path& scene) {
    std::vector<ObjectState> out;
    const SectionEntry* e = r.find(section::geo_objects);
    if (!e || e->element_size != sizeof(ObjectReference)) return out;
    for (const ObjectReference& o : r.section<ObjectReference>(section::geo_objects)) {
        ObjectState s{std::string(o.path, strnlen(o.path, kObjectPathBytes)), o.content_hash, o.triangle_count, ""};
        try {
            const auto object = ContainerReader::open(scene.parent_path() / s.path, FileKind::geometry);
            s.state = object.header().section_table_checksum == o.content_hash ? "current" : "changed since the scene was built";
        } catch (const std::exception& ex) {
            s.state = ex.what();
        }
        out.push_back(std::move(s));
    }
    return out;
}

void print_text(const ContainerReader& r, const std::filesystem::path& path) {
    const auto& h = r.header();
    const auto& info = file_kind_info(r.kind());
    std::cout << r.name() << ": kdpm " << info.name << ", format " << h.version_major << "." << h.version_minor
              << ", " << h.file_size << " bytes, " << h.section_count << " sections\n";
    std::printf("  %-26s %-7s %8s %12s %12s  %s\n", "section", "type", "elem", "count", "bytes", "xxh3");
    for (const auto& e : r.sections()) {
        auto name = section::name(e.id);
        char id[16];
        std::snprintf(id, sizeof id, "0x%x", e.id);
        std::printf("  %-26s %-7s %8u %12llu %12llu  %s\n", name.empty() ? id : std::string(name).c_str(),
                    type_name(e.element_type), e.element_size, static_cast<unsigned long long>(e.count),
                    static_cast<unsigned long long>(e.byte_size), hex(e.checksum).c_str());
    }
    if (r.has_metadata()) {
        Metadata m = r.metadata();
        std::cout << "metadata:\n  made by  " << m.tool << " " << m.tool_version << "\n  source   " << m.source_path
                  << " (xxh3 " << m.source_hash << ")\n";
        for (const auto& [k, v] : m.parameters) std::cout << "  param    " << k << " = " << v << "\n";
        for (const auto& [k, v] : m.statistics) std::cout << "  stat     " << k << " = " << v << "\n";
    }
    const auto objects = object_states(r, path);
    if (!objects.empty()) std::cout << "objects:\n";
    for (const ObjectState& o : objects)
        std::cout << "  " << o.path << ": " << o.triangles << " triangles, xxh3 " << hex(o.hash) << ", " << o.state << "\n";
}

void print_json(const ContainerReader& r, const std::filesystem::path& path) {
    using cli::json_string;
    const auto& h = r.header();
    const auto& info = file_kind_info(r.kind());
    std::ostringstream o;
    o << "{\n  \"file\": " << json_string(r.name()) << ",\n  \"kind\": " << json_string(std::string(info.name))
      << ",\n  \"version\": \"" << h.version_major << "." << h.version_minor << "\",\n  \"file_size\": " << h.file_size
      << ",\n  \"sections\": [";
    bool first = true;
    for (const auto& e : r.sections()) {
        o << (first ? "\n" : ",\n") << "    {\"id\": " << e.id << ", \"name\": " << json_string(std::string(section::name(e.id)))
          << ", \"type\": \"" << type_name(e.element_type) << "\", \"element_size\": " << e.element_size
          << ", \"count\": " << e.count << ", \"offset\": " << e.offset << ", \"bytes\": " << e.byte_size
          << ", \"xxh3\": \"" << hex(e.checksum) << "\"}";
        first = false;
    }
    o << "\n  ]";
    const auto objects = object_states(r, path);
    if (!objects.empty()) {
        o << ",\n  \"objects\": [";
        for (std::size_t i = 0; i < objects.size(); ++i)
            o << (i ? ",\n" : "\n") << "    {\"path\": " << json_string(objects[i].path) << ", \"triangles\": "
              << objects[i].triangles << ", \"xxh3\": \"" << hex(objects[i].hash) << "\", \"state\": "
              << json_string(objects[i].state) << "}";
        o << "\n  ]";
    }
    if (r.has_metadata()) {
        Metadata m = r.metadata();
        o << ",\n  \"metadata\": " << metadata_to_json(m);
    }
    o << "\n}\n";
    std::cout << o.str();
}

}  // namespace

int main(int argc, char** argv) {
    std::string path;
    bool json = false;
    cli::Args args("kdpm-inspect", "Prints the kind, version, sections and metadata of a kdpm file.");
    args.positional("FILE", &path, "a .kdg, .kdph or .kdp file").flag("json", &json, "print JSON for pipelines");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-inspect", [&] {
        auto reader = ContainerReader::open(path);
        json ? print_json(reader, path) : print_text(reader, path);
        return 0;
    });
}
