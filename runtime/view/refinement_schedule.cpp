#include "runtime/view/refinement_schedule.h"

#include <algorithm>

namespace kdpm {

RefinementSchedule::RefinementSchedule(std::uint32_t width, std::uint32_t height, std::uint32_t max_spp,
                                       std::uint32_t preview_divisor)
    : width_(width), height_(height), max_spp_(std::max<std::uint32_t>(1, max_spp)),
      divisor_(std::max<std::uint32_t>(1, preview_divisor)) {
    restart(false);
}

void RefinementSchedule::restart(bool preview) {
    preview_ = preview && divisor_ > 1;
    spp_ = 1;
    shown_ = 0;
    done_ = false;
}

std::optional<RefinementStep> RefinementSchedule::current() const {
    if (done_) return std::nullopt;
    RefinementStep s;
    if (preview_) {
        s.width = std::max<std::uint32_t>(1, width_ / divisor_);
        s.height = std::max<std::uint32_t>(1, height_ / divisor_);
        s.spp = 1;
        s.first_sample = 0;
        s.sequence_spp = 1;
        s.preview = true;
    } else {
        s.width = width_;
        s.height = height_;
        s.spp = spp_;
        s.first_sample = shown_;
        s.sequence_spp = max_spp_;
    }
    return s;
}

void RefinementSchedule::advance() {
    if (done_) return;
    if (preview_) {
        preview_ = false;
        return;
    }
    shown_ = spp_;
    if (spp_ >= max_spp_)
        done_ = true;
    else
        spp_ = std::min(spp_ * 2, max_spp_);
}

}  // namespace kdpm
