// kdpm-merge-photons PART.kdph... -o PHOTONS.kdph: joins the shards of one photon shooting run
// (kdpm-shoot-photons --paths BEGIN:END) in path order into the file the whole run writes.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "builders/photons/photon_hits_file.h"
#include "builders/photons/photon_shards.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

int main(int argc, char** argv) {
    std::vector<std::string> inputs;
    std::string output;
    bool quiet = false;
    cli::Args args("kdpm-merge-photons",
                   "Merges photon hit shards (kdpm-shoot-photons --paths) into the photon hit file of the whole run.");
    args.positionals("PART.kdph", &inputs, "shards, in any order, covering every path exactly once")
        .option("output", &output, "FILE.kdph", "output file")
        .flag("quiet", &quiet, "print nothing on success");
    args.short_name('o', "output");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-merge-photons", [&] {
        if (output.empty()) throw std::invalid_argument("no output file (use -o FILE.kdph)");
        std::vector<PhotonShard> shards;
        for (const auto& input : inputs) {
            std::error_code ec;
            if (std::filesystem::equivalent(input, output, ec))
                throw std::invalid_argument("the output " + output + " is one of the shards");
            shards.push_back(read_photon_shard(input));
        }
        const std::size_t count = shards.size();
        MergedPhotons merged = merge_photon_shards(std::move(shards));
        photon_hits_writer(merged.set, merged.metadata).write(output);
        if (!quiet)
            std::printf("kdpm-merge-photons: %zu shards, %llu paths, %u stored (%u caustic) -> %s\n", count,
                        static_cast<unsigned long long>(merged.set.info.emitted_count), merged.set.info.stored_count,
                        merged.set.info.caustic_count, output.c_str());
        return 0;
    });
}
