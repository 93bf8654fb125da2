#include "runtime/view/refinement_folding.h"

#include <algorithm>
#include <stdexcept>

#include "runtime/render/image/post_process.h"

namespace kdpm {

void render_new_samples(const RefinementStep& step, RenderSettings& s) {
    s.first_sample = step.first_sample;
    s.spp = step.new_samples();
    s.sequence_spp = step.sequence_spp;
}

void fold_samples(const Image& before, std::uint32_t samples_before, Image& frame, std::uint32_t added) {
    if (before.width != frame.width || before.height != frame.height || before.rgb.size() != frame.rgb.size())
        throw std::invalid_argument("cannot fold samples into an image of another size");
    const double total = static_cast<double>(samples_before) + static_cast<double>(added);
    if (total <= 0.0) return;
    const float w_before = static_cast<float>(samples_before / total);
    const float w_added = static_cast<float>(added / total);
    for (std::size_t i = 0; i < frame.rgb.size(); ++i) frame.rgb[i] = w_before * before.rgb[i] + w_added * frame.rgb[i];
}

std::uint32_t fold_refinement(FinishedFrame& frame, const FinishedFrame* shown, std::uint32_t shown_samples) {
    const RenderSettings& s = frame.job.settings;
    const std::uint32_t own = std::max<std::uint32_t>(1, s.spp);
    const bool continues = s.first_sample > 0 && shown != nullptr && shown->job.generation == frame.job.generation &&
                           shown_samples == s.first_sample && shown->result.linear.width == frame.result.linear.width &&
                           shown->result.linear.height == frame.result.linear.height;
    if (!continues) return own;
    fold_samples(shown->result.linear, shown_samples, frame.result.linear, own);
    RenderResult& r = frame.result;
    post_process(r.linear, r.post, r.exposed, r.display);
    return shown_samples + own;
}

}  // namespace kdpm
