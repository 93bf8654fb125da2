#pragma once
// Which frame to render next for progressive display: while the camera moves, one preview at
// reduced resolution; once it stops, full resolution with 1, 2, 4, ... samples per pixel up to
// a cap. Each full-resolution step renders only the samples the shown image lacks (first_sample
// on), which the viewer averages into it: the cap is reached for the cost of one render at the
// cap, where fresh renders of 1, 2, 4, ... samples cost up to twice that.
#include <cstdint>
#include <optional>

namespace kdpm {

struct RefinementStep {
    std::uint32_t width = 0, height = 0;
    std::uint32_t spp = 1;           // samples per pixel shown once this step's frame is in
    std::uint32_t first_sample = 0;  // samples shown before it: the frame renders first_sample .. spp - 1
    std::uint32_t sequence_spp = 1;  // the run the samples belong to (the cap; 1 for a preview)
    bool preview = false;
    std::uint32_t new_samples() const { return spp - first_sample; }
};

class RefinementSchedule {
public:
    // preview_divisor: the preview's resolution is full / divisor per axis (at least 1 pixel).
    RefinementSchedule(std::uint32_t width, std::uint32_t height, std::uint32_t max_spp, std::uint32_t preview_divisor);

    // Starts over after a change; with `preview` the first step is a reduced-resolution frame.
    void restart(bool preview);
    std::optional<RefinementStep> current() const;  // empty once the cap is reached
    void advance();                                 // the current step's frame was shown

    std::uint32_t max_spp() const { return max_spp_; }

private:
    std::uint32_t width_, height_, max_spp_, divisor_;
    bool preview_ = false;
    std::uint32_t spp_ = 1, shown_ = 0;  // this step's total, and the samples shown before it
    bool done_ = false;
};

}  // namespace kdpm
