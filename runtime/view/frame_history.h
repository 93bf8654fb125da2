#pragma once
// Per-stage times of the last frames the viewer showed, oldest first, for the panel's plot.
#include <cstddef>
#include <vector>

namespace kdpm {

struct StageSample {
    float trace_ms = 0, gather_ms = 0, shade_ms = 0, post_ms = 0;
    float total() const { return trace_ms + gather_ms + shade_ms + post_ms; }
};

class FrameHistory {
public:
    explicit FrameHistory(std::size_t capacity = 120) : capacity_(capacity ? capacity : 1) {}

    void push(const StageSample& s) {
        if (samples_.size() < capacity_) {
            samples_.push_back(s);
        } else {
            samples_[next_] = s;
            next_ = (next_ + 1) % capacity_;
        }
    }
    std::size_t size() const { return samples_.size(); }

    // One stage over the kept frames, oldest first.
    template <class Stage>
    std::vector<float> series(Stage stage) const {
        std::vector<float> out;
        out.reserve(samples_.size());
        for (std::size_t i = 0; i < samples_.size(); ++i) out.push_back(stage(samples_[(next_ + i) % samples_.size()]));
        return out;
    }

private:
    std::size_t capacity_;
    std::size_t next_ = 0;  // oldest sample once full
    std::vector<StageSample> samples_;
};

}  // namespace kdpm
