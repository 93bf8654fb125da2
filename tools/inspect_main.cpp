// kdpm-inspect FILE: what is this kdpm file, what does it hold, and what made it.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "formats/container_reader.h"
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

void print_text(const ContainerReader& r) {
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
}

void print_json(const ContainerReader& r) {
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
        json ? print_json(reader) : print_text(reader);
        return 0;
    });
}
