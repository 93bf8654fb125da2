#include "tools/bench/quality_report.h"

#include <algorithm>
#include <cmath>

#include "tools/bench/text_table.h"

namespace kdpm::bench {
namespace {

std::string deviation(double ratio) { return ratio > 0 ? fmt("%+.1f %%", 100.0 * (ratio - 1.0)) : "-"; }
std::string relmse(double v) { return fmt("%.4g", v); }
std::string secs(double v) { return fmt("%.3f", v); }
std::string verdict(bool met) { return met ? "met" : "MISSED"; }

const Ladder* find(const QualityResult& r, const std::string& mode) {
    for (const auto& l : r.ladders)
        if (l.mode == mode) return &l;
    return nullptr;
}

std::string error_table(const QualityResult& r, bool md) {
    Table t{{"mode", "setting", "time (s)", "relMSE", "mean vs ref", "top third", "middle third", "bottom third"}, {}};
    for (const auto& l : r.ladders)
        for (const auto& g : l.rungs)
            t.rows.push_back({l.mode, g.setting, secs(g.seconds), relmse(g.relmse), deviation(g.mean_ratio),
                              deviation(g.third_ratio[0]), deviation(g.third_ratio[1]), deviation(g.third_ratio[2])});
    return t.render(md);
}

std::string equal_time_table(const QualityResult& r, bool md) {
    Table t{{fmt("equal time (<= %g s)", r.seconds), "best setting", "time (s)", "relMSE", "top third", "middle third",
             "bottom third"},
            {}};
    for (const auto& l : r.ladders) {
        const Rung* b = best_within(l, r.seconds);
        if (!b) {
            t.rows.push_back({l.mode, l.rungs.empty() ? "-" : "(its cheapest rung took " + secs(l.rungs.front().seconds) + " s)",
                              "-", "-", "-", "-", "-"});
            continue;
        }
        t.rows.push_back({l.mode, b->setting, secs(b->seconds), relmse(b->relmse), deviation(b->third_ratio[0]),
                          deviation(b->third_ratio[1]), deviation(b->third_ratio[2])});
    }
    return t.render(md);
}

// relMSE of each ladder's best rung within each budget (issue 51: 1, 2, 4 and 8 s).
std::string budget_table(const QualityResult& r, bool md) {
    if (r.budgets.empty()) return {};
    Table t{{"relMSE at equal time"}, {}};
    for (double b : r.budgets) t.header.push_back(fmt("<= %g s", b));
    for (const auto& l : r.ladders) {
        std::vector<std::string> row{l.mode};
        for (double b : r.budgets) {
            const Rung* best = best_within(l, b);
            row.push_back(best ? relmse(best->relmse) : "-");
        }
        t.rows.push_back(row);
    }
    return t.render(md);
}

// Where each ladder's best rung within the budget errs: near geometric edges or on flat parts.
std::string region_table(const QualityResult& r, bool md) {
    Table t{{fmt("where the error is (<= %g s)", r.seconds), "edges relMSE", "edges mean", "edges' share of error",
             "flat relMSE", "flat mean", "picture"},
            {}};
    for (const auto& l : r.ladders) {
        const Rung* b = best_within(l, r.seconds);
        if (!b) continue;
        const RegionSplit& g = b->regions;
        t.rows.push_back({l.mode, relmse(g.edges.relmse), deviation(g.edges.mean_ratio),
                          fmt("%.0f %%", 100.0 * g.edges.error_share), relmse(g.flat.relmse), deviation(g.flat.mean_ratio),
                          l.picture.empty() ? "-" : l.picture.filename().string()});
    }
    return t.render(md);
}

std::string verdicts(const QualityResult& r) {
    std::string out;
    const Ladder* fg = find(r, ladder_label(RenderMode::final_gather, kCachedGather));
    const Rung* cached = fg ? best_within(*fg, r.seconds) : nullptr;
    for (const RenderMode other_mode : {RenderMode::photons, RenderMode::direct_photons}) {
        const std::string label = ladder_label(other_mode);
        const char* other = label.c_str();
        const Ladder* l = find(r, label);
        const Rung* o = l ? best_within(*l, r.seconds) : nullptr;
        if (!cached || !o) {
            out += fmt("- final-gather + cache relMSE <= 1/4 of %s at %g s: %s\n", other, r.seconds,
                       cached ? "no rung of the other mode within the budget" : "MISSED (no rung within the budget)");
            continue;
        }
        out += fmt("- final-gather + cache relMSE <= 1/4 of %s at %g s: %.4g vs %.4g (%.2fx; target <= 0.25x): %s\n",
                   other, r.seconds, cached->relmse, o->relmse, cached->relmse / o->relmse,
                   verdict(cached->relmse <= 0.25 * o->relmse).c_str());
    }
    if (fg) {
        // Bias, not noise: every rung that took more than a second.
        double worst = 0;
        int rungs = 0;
        for (const Rung& g : fg->rungs) {
            if (g.seconds <= 1.0) continue;
            ++rungs;
            for (double ratio : g.third_ratio) worst = std::max(worst, std::fabs(ratio - 1.0));
        }
        if (rungs > 0)
            out += fmt("- final-gather + cache mean within 1 %% of the reference in every third at every rung past 1 s "
                       "(%d rungs): worst %.1f %%: %s\n",
                       rungs, 100.0 * worst, verdict(worst <= 0.01).c_str());
    }
    if (const Ladder* sppm = find(r, ladder_label(RenderMode::sppm)); sppm && !sppm->rungs.empty()) {
        const auto lowest = std::min_element(sppm->rungs.begin(), sppm->rungs.end(),
                                             [](const Rung& a, const Rung& b) { return a.relmse < b.relmse; });
        out += fmt("- sppm reaches relMSE <= 0.01: lowest %.4g (%s, %.1f s): %s\n", lowest->relmse,
                   lowest->setting.c_str(), lowest->seconds, verdict(lowest->relmse <= 0.01).c_str());
        int rises = 0;
        std::string curve;
        for (std::size_t i = 0; i < sppm->rungs.size(); ++i) {
            if (i > 0 && sppm->rungs[i].relmse >= sppm->rungs[i - 1].relmse) ++rises;
            curve += (i ? ", " : "") + sppm->rungs[i].setting + " " + relmse(sppm->rungs[i].relmse);
        }
        out += fmt("- sppm keeps falling with passes (%d of %zu doublings did not lower it): %s\n", rises,
                   sppm->rungs.size() > 0 ? sppm->rungs.size() - 1 : 0, verdict(rises == 0).c_str());
        out += "- sppm curve (relMSE): " + curve + "\n";
    }
    return out;
}

}  // namespace

const Rung* best_within(const Ladder& ladder, double seconds) {
    const Rung* best = nullptr;
    for (const auto& g : ladder.rungs)
        if (g.seconds <= seconds && (!best || g.relmse < best->relmse)) best = &g;
    return best;
}

std::string format_quality_report(const std::vector<QualityResult>& results, bool md) {
    std::string out;
    for (const auto& r : results) {
        const std::string bounces = r.max_bounces ? std::to_string(r.max_bounces) + " diffuse bounces" : "unlimited bounces";
        const std::string title = fmt("%s, %ux%u, %d threads", r.name.c_str(), r.size, r.size, r.threads);
        out += md ? "\n### " + title + "\n\n" : "\n== " + title + " ==\n";
        out += fmt("reference: --mode path, %u spp, %s, %s %s\n", r.reference_spp, bounces.c_str(),
                   r.reference_reused ? "reused from" : fmt("rendered in %.1f s (%s), cached as", r.reference_render_seconds,
                                                        r.reference_backend == "cpu" ? "CPU, every core" : r.reference_backend.c_str()).c_str(),
                   r.reference_file.string().c_str());
        out += fmt("%sphoton map (photons, direct+photons, final-gather): photons of up to %u bounces\n", md ? "\n" : "",
                   r.photon_bounces);
        out += fmt("%s(path shares its first samples with the reference: its relMSE at n spp reads low by a factor 1 - n/%u)\n\n",
                   md ? "\n" : "", r.reference_spp);
        out += error_table(r, md);
        out += "\n";
        out += equal_time_table(r, md);
        out += "\n";
        out += budget_table(r, md);
        out += "\n";
        out += fmt("edges: pixels within 2 of a crease, silhouette or depth step (%.0f %% of the image)%s\n\n",
                   100.0 * r.edge_share, md ? "\n" : "");
        out += region_table(r, md);
        if (!r.ladders.empty() && !r.ladders.front().picture.empty())
            out += fmt("%spictures (test | reference | error: red too bright, blue too dark, full at 1 stop) in %s\n",
                       md ? "\n" : "", r.ladders.front().picture.parent_path().string().c_str());
        out += "\n";
        out += verdicts(r);
    }
    return out;
}

}  // namespace kdpm::bench
