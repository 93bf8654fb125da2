#pragma once
// Caps oneTBB's worker count for the life of the object (tools' --threads, determinism tests).
#include <memory>

#include <tbb/global_control.h>

namespace kdpm {

class ThreadLimit {
public:
    explicit ThreadLimit(int threads) {
        if (threads > 0)
            control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                             static_cast<std::size_t>(threads));
    }

private:
    std::unique_ptr<tbb::global_control> control_;
};

}  // namespace kdpm
