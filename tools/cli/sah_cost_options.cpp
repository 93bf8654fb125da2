#include "tools/cli/sah_cost_options.h"

namespace kdpm::cli {

void add_sah_cost_options(Args& args, SahCosts& costs) {
    args.option("traversal-cost", &costs.traversal, "C", "SAH cost of an inner node step (default 1)", 0.0, 1e6)
        .option("intersection-cost", &costs.intersection, "C", "SAH cost of a ray/triangle test (default 1)", 1e-6,
                1e6)
        .option("empty-bonus", &costs.empty_bonus, "B", "cost reduction for splits with an empty side, 0..1 (default 0.2)",
                0.0, 1.0);
}

KdBuildParams with_costs(KdBuildParams params, const SahCosts& costs) {
    params.traversal_cost = static_cast<float>(costs.traversal);
    params.intersection_cost = static_cast<float>(costs.intersection);
    params.empty_bonus = static_cast<float>(costs.empty_bonus);
    return params;
}

}  // namespace kdpm::cli
