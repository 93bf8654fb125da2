#pragma once
// The SAH cost options of the geometry build (--traversal-cost, --intersection-cost,
// --empty-bonus), declared once for every tool that builds geometry kd-trees: the builder and
// the benchmarks that time a build, or trace through one, for the costs a user picks.
#include "builders/geometry/sah/kd_build_params.h"
#include "tools/cli/args.h"

namespace kdpm::cli {

struct SahCosts {
    double traversal = KdBuildParams{}.traversal_cost;
    double intersection = KdBuildParams{}.intersection_cost;
    double empty_bonus = KdBuildParams{}.empty_bonus;
};

// Declares the three options on `args`, with their ranges, writing into `costs`.
void add_sah_cost_options(Args& args, SahCosts& costs);

// `params` with the parsed costs.
KdBuildParams with_costs(KdBuildParams params, const SahCosts& costs);

}  // namespace kdpm::cli
