// kdpm-validate FILE: exit 0 when the file is sound, else a one-line reason and exit 1.
#include <filesystem>
#include <iostream>

#include "formats/container_reader.h"
#include "formats/output_file.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "runtime/geometry/geometry_file.h"

using namespace kdpm;

int main(int argc, char** argv) {
    std::string path;
    bool quiet = false;
    ValidationOptions options;
    cli::Args args("kdpm-validate", "Checks a kdpm file: container, checksums and the tree's structural invariants.");
    args.positional("FILE", &path, "a .kdg, .kdph or .kdp file")
        .flag("exhaustive", &options.exhaustive, "also run the slow checks (full leaf coverage)")
        .flag("quiet", &quiet, "print nothing when the file is sound");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-validate", [&] {
        // A temporary of an interrupted write is never a valid file, however its bytes look.
        if (is_output_temporary_name(std::filesystem::path(path).filename().string()))
            throw FormatError(path + ": a temporary left by an interrupted kdpm write; safe to delete");
        auto reader = ContainerReader::open(path);
        validate_file(reader, options);
        // A scene of instances is sound only with its objects: each opened and checked, its
        // content hash compared with the scene's.
        if (reader.find(section::geo_instances)) GeometryFile::open(path);
        if (!quiet) std::cout << path << ": ok (" << file_kind_info(reader.kind()).name << ")\n";
        return 0;
    });
}
