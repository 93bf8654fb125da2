#pragma once
// Which frame to render next for progressive display: while the camera moves, one preview at
// reduced resolution; once it stops, full resolution with 1, 2, 4, ... samples per pixel up to
// a cap. Every frame is a fresh render of spp samples (the Renderer has no sample offset to
// resume from), so reaching the cap costs at most twice a single render at the cap.
#include <cstdint>
#include <optional>

namespace kdpm {

struct RefinementStep {
    std::uint32_t width = 0, height = 0, spp = 1;
    bool preview = false;
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
    std::uint32_t spp_ = 1;
    bool done_ = false;
};

}  // namespace kdpm
