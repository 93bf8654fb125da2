// kdpm-bench's ratio of two stages timed in pairs: the median of the pairs' ratios, which a slow
// stretch of the host shared by both halves of a pair does not move.
#include <catch2/catch.hpp>

#include <vector>

#include "tools/bench/median_time.h"

using kdpm::bench::median_of;
using kdpm::bench::median_ratio;

TEST_CASE("median_ratio takes the median of the per-pair ratios", "[tools][bench]") {
    // Passes run o1 p1 o2 p2 ... o5 p5; ours takes 1.1x the peer's time on the same machine.
    // The host slows 3x from o2 to p3: both halves of pairs 2 and 3.
    const std::vector<double> ours{11.0, 33.0, 33.0, 11.0, 11.0};
    const std::vector<double> peer{10.0, 30.0, 30.0, 10.0, 10.0};
    CHECK(median_ratio(ours, peer) == Approx(1.1));

    // It slows from o3 to o5 instead: three of our passes, two of the peer's. The quotient of
    // the medians reads 3.3x; the pairs' ratios are 1.1x but for the last.
    const std::vector<double> ours_slow{11.0, 11.0, 33.0, 33.0, 33.0};
    const std::vector<double> peer_slow{10.0, 10.0, 30.0, 30.0, 10.0};
    CHECK(median_of(ours_slow) / median_of(peer_slow) == Approx(3.3));
    CHECK(median_ratio(ours_slow, peer_slow) == Approx(1.1));
}

TEST_CASE("median_ratio skips pairs without a time and ignores unpaired passes", "[tools][bench]") {
    CHECK(median_ratio({}, {}) == 0.0);
    CHECK(median_ratio({5.0, 0.0}, {0.0, 2.0}) == 0.0);
    CHECK(median_ratio({4.0, 0.0, 9.0}, {2.0, 1.0, 3.0}) == Approx(3.0));  // pairs 1 and 3: 2x, 3x -> upper median
    CHECK(median_ratio({6.0, 8.0, 100.0}, {2.0}) == Approx(3.0));         // only the first pass has a partner
}
