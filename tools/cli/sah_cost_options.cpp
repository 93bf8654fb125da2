#include "tools/cli/sah_cost_options.h"

#include <cstdio>
#include <string>

namespace kdpm::cli {

namespace {

// The help's "(default X)" read from KdBuildParams, so the text follows the builder's defaults.
std::string with_default(const char* help, float value) {
    char text[32];
    std::snprintf(text, sizeof text, " (default %g)", static_cast<double>(value));
    return help + std::string(text);
}

}  // namespace

void add_sah_cost_options(Args& args, SahCosts& costs) {
    const KdBuildParams defaults;
    args.option("traversal-cost", &costs.traversal, "C",
                with_default("SAH cost of an inner node step", defaults.traversal_cost), 0.0, 1e6)
        .option("intersection-cost", &costs.intersection, "C",
                with_default("SAH cost of a ray/triangle test", defaults.intersection_cost), 1e-6, 1e6)
        .option("empty-bonus", &costs.empty_bonus, "B",
                with_default("cost reduction for splits with an empty side, 0..1", defaults.empty_bonus), 0.0, 1.0);
}

KdBuildParams with_costs(KdBuildParams params, const SahCosts& costs) {
    params.traversal_cost = static_cast<float>(costs.traversal);
    params.intersection_cost = static_cast<float>(costs.intersection);
    params.empty_bonus = static_cast<float>(costs.empty_bonus);
    return params;
}

}  // namespace kdpm::cli
