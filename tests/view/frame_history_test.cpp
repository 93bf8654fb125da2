#include <catch2/catch.hpp>

#include "runtime/view/frame_history.h"

using namespace kdpm;

TEST_CASE("frame history keeps the last frames, oldest first", "[view][history]") {
    FrameHistory history(4);
    auto trace = [](const StageSample& s) { return s.trace_ms; };
    CHECK(history.series(trace).empty());
    for (int i = 1; i <= 3; ++i) history.push({float(i), 0, 0, 0});
    CHECK(history.series(trace) == std::vector<float>{1, 2, 3});
    for (int i = 4; i <= 10; ++i) history.push({float(i), 1, 2, 3});
    CHECK(history.size() == 4);
    CHECK(history.series(trace) == std::vector<float>{7, 8, 9, 10});
    CHECK(history.series([](const StageSample& s) { return s.total(); }) == std::vector<float>{13, 14, 15, 16});
}
