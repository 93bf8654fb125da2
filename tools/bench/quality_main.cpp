// kdpm-bench-quality: error against time for every lighting mode, measured against a converged
// --mode path reference, and the equal-time comparison of issue 14's targets.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "runtime/backend/backend_kind.h"
#include "tools/bench/quality_bench.h"
#include "tools/bench/quality_report.h"
#include "tools/bench/scenes_root.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// References take long to render: by default they are kept in the user's cache folder.
fs::path default_work_dir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "kdpm" / "bench-quality";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "kdpm" / "bench-quality";
    return fs::temp_directory_path() / "kdpm-bench-quality";
}

// "1,2,4,8": positive seconds, at most 8 of them.
std::vector<double> parse_budgets(const std::string& text) {
    std::vector<double> out;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        double v = 0;
        try {
            v = cli::parse_finite(item);
        } catch (const std::invalid_argument&) {
            v = 0;  // refused below
        }
        if (!(v > 0.0 && v <= 1e6))
            throw std::invalid_argument("budgets are seconds in (0, 1e6] separated by commas, got '" + item + "'");
        out.push_back(v);
    }
    if (out.empty() || out.size() > 8) throw std::invalid_argument("give 1 to 8 budgets, got '" + text + "'");
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    bool markdown = false, quiet = false;
    int size = 512, threads = 2, reference_spp = 4096, max_bounces = 0, photons = 0, max_rungs = 12;
    int photon_bounces = -1;
    double seconds = 2.0, sppm_seconds = 30.0;
    std::string scenes_arg = "cornell-box,sponza,conference", scenes_root, work, pictures;
    std::vector<double> budgets{1, 2, 4, 8};
    bool breakdown = false;
    BackendRequest reference_backend = BackendRequest::automatic;
    cli::Args args("kdpm-bench-quality",
                   "Error against time of every lighting mode, against a converged path-traced reference.");
    args.flag("markdown", &markdown, "print Markdown tables")
        .option("scenes", &scenes_arg, "LIST", "comma-separated: cornell-box,sponza,conference (default all found)")
        .option("size", &size, "N", "image width and height (default 512)", 8, 4096)
        .option("threads", &threads, "N", "threads of the timed renders (default 2; a CPU reference uses every core)", 1, 1024)
        .option("reference-spp", &reference_spp, "N", "samples per pixel of the path-traced reference (default 4096)", 1,
                1 << 20)
        .option("reference-backend", "auto|cpu|cuda",
                "where the reference renders (default auto: CUDA when a device exists, else every CPU core)",
                [&](const std::string& v) { reference_backend = parse_backend_request(v); })
        .option("max-bounces", &max_bounces, "N",
                "diffuse bounces of the reference, path and sppm (default 0: unlimited)", 0, 1000)
        .option("photons", &photons, "N", "photon paths of the .kdp (default: the scene card's)", 0, 1 << 26)
        .option("photon-bounces", &photon_bounces, "N",
                "bounces of the .kdp's photons (default: the scene card's; 0: unlimited, as the reference's default)", 0, 255)
        .option("seconds", &seconds, "S", "the equal-time budget (default 2)", 1e-3, 1e6)
        .option("budgets", "LIST", "the equal-time table's budgets in seconds (default 1,2,4,8); ladders run past the last",
                [&](const std::string& v) { budgets = parse_budgets(v); })
        .flag("breakdown", &breakdown,
              "also final gathering with the k-nearest estimate and with a path traced on at the gather hits "
              "(--gather-lookup): which part of the error is the photon map's")
        .option("pictures", &pictures, "DIR",
                "where the test | reference | error PNG of each mode goes (default: pictures/ in the work folder)")
        .option("sppm-seconds", &sppm_seconds, "S", "sppm's curve runs until a rung takes this long (default 30)", 0, 1e6)
        .option("max-rungs", &max_rungs, "N", "most settings per mode (default 12)", 1, 17)
        .option("repo", &scenes_root, "DIR", "folder holding scenes/ (default: the working directory or a parent, else found from the executable)")
        .option("work", &work, "DIR", "where the .kdg/.kdp files and the cached references go (default ~/.cache/kdpm/bench-quality)")
        .flag("quiet", &quiet, "no progress lines on stderr");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-bench-quality", [&] {
        const fs::path root = bench::find_scenes_root(scenes_root, argv[0]);
        const fs::path dir = work.empty() ? default_work_dir() : fs::path(work);
        fs::create_directories(dir);
        const bool talk = cli::interactive(quiet);

        std::vector<bench::QualityResult> results;
        std::string name;
        std::stringstream list(scenes_arg);
        while (std::getline(list, name, ',')) {
            const fs::path card = root / "scenes" / name / (name + ".json");
            if (!fs::exists(card)) throw std::runtime_error("no scene card " + card.string());
            bench::QualityConfig c;
            c.name = name;
            c.card = card;
            c.work_dir = dir;
            c.size = static_cast<std::uint32_t>(size);
            c.threads = threads;
            c.reference_spp = static_cast<std::uint32_t>(reference_spp);
            c.reference_backend = reference_backend;
            c.max_bounces = static_cast<std::uint32_t>(max_bounces);
            c.photons = static_cast<std::uint32_t>(photons);
            c.photon_bounces = photon_bounces;
            c.seconds = seconds;
            c.budgets = budgets;
            c.breakdown = breakdown;
            c.images_dir = pictures.empty() ? dir / "pictures" : fs::path(pictures);
            c.sppm_seconds = sppm_seconds;
            c.max_rungs = max_rungs;
            c.progress_bar = talk;
            if (talk) c.say = [name](const std::string& what) { std::fprintf(stderr, "  [%s] %s\n", name.c_str(), what.c_str()); };
            try {
                results.push_back(bench::run_quality_bench(c));
            } catch (const std::exception& e) {
                // A shared scene that is absent is skipped with a message; the shipped one must work.
                if (name == "cornell-box") throw;
                std::fprintf(stderr, "kdpm-bench-quality: skipping %s: %s\n", name.c_str(), e.what());
            }
        }
        std::cout << bench::format_quality_report(results, markdown);
        return 0;
    });
}
