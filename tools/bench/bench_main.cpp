// kdpm-bench: the report's performance table on this machine, with its figures and the peers'
// (Embree, nanoflann) beside kdpm's, for the Cornell box and the shared Sponza and Conference.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "tools/bench/bench_report.h"
#include "tools/bench/host_description.h"
#include "tools/bench/scene_bench.h"
#include "tools/bench/scenes_root.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "tools/cli/sah_cost_options.h"

using namespace kdpm;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
    bool markdown = false, quiet = false, no_peers = false, quick = false, all_threads_only = false;
    int frames = 3, photons = 262144, size = 512, grid = 100;
    std::string scenes_arg = "cornell-box,sponza,conference", scenes_root, work;
    cli::Args args("kdpm-bench", "Reproduces the report's timing table on this machine, with peers in the same run.");
    args.flag("markdown", &markdown, "print Markdown tables")
        .option("scenes", &scenes_arg, "LIST", "comma-separated: cornell-box,sponza,conference (default all found)")
        .option("frames", &frames, "N", "frames (and builds) per median (default 3)", 1, 100)
        .option("photons", &photons, "N", "photons emitted (default 262144, as the report)", 1, 1 << 26)
        .option("size", &size, "N", "image width and height (default 512)", 8, 4096)
        .option("repo", &scenes_root, "DIR", "folder holding scenes/ (default: the working directory or a parent, else found from the executable)")
        .option("work", &work, "DIR", "where the .kdg/.kdp files go (default: a temporary folder)")
        .option("instance-grid", &grid, "N", "instance rows: the scene placed N x N times (default 100: 10^4 instances; 0: none)", 0, 1000)
        .flag("no-peers", &no_peers, "skip Embree and nanoflann")
        .flag("quick", &quick, "k = 2, 32, 256 only")
        .flag("all-threads-only", &all_threads_only, "no 1-thread rows (a GPU machine's check, short of time)")
        .flag("quiet", &quiet, "no progress lines on stderr");
    cli::SahCosts costs;  // of every geometry build: time the whole table for the costs a pipeline uses
    cli::add_sah_cost_options(args, costs);
    args.parse(argc, argv);
    return cli::run_tool("kdpm-bench", [&] {
        const fs::path root = bench::find_scenes_root(scenes_root, argv[0]);
        fs::path dir = work.empty() ? fs::temp_directory_path() / ("kdpm-bench-" + std::to_string(::getpid())) : fs::path(work);
        fs::create_directories(dir);
        const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

        std::vector<bench::SceneBenchResult> results;
        std::string name;
        std::stringstream list(scenes_arg);
        while (std::getline(list, name, ',')) {
            fs::path card = root / "scenes" / name / (name + ".json");
            if (!fs::exists(card)) throw std::runtime_error("no scene card " + card.string());
            bench::SceneBenchConfig c;
            c.name = name;
            c.card = card;
            c.work_dir = dir;
            c.threads = all > 1 && !all_threads_only ? std::vector<int>{1, all} : std::vector<int>{all};
            c.ks = quick ? std::vector<int>{2, 32, 256} : std::vector<int>{2, 4, 8, 16, 32, 64, 128, 256};
            c.frames = frames;
            c.width = c.height = static_cast<std::uint32_t>(size);
            c.photons = static_cast<std::uint32_t>(photons);
            c.peers = !no_peers;
            c.quiet = quiet;
            c.instance_grid = static_cast<std::uint32_t>(grid);
            c.build = cli::with_costs(KdBuildParams{}, costs);
            try {
                results.push_back(bench::run_scene_bench(c));
            } catch (const std::exception& e) {
                // A shared scene that is absent is skipped with a message; the shipped one must work.
                if (name == "cornell-box") throw;
                std::fprintf(stderr, "kdpm-bench: skipping %s: %s\n", name.c_str(), e.what());
            }
        }
        if (work.empty()) fs::remove_all(dir);
        std::cout << "\n" << bench::host_description() << "\n" << bench::format_report(results, markdown);
        return 0;
    });
}
