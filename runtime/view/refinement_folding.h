#pragma once
// kdpm-view's refinement frames render only the samples the shown image lacks
// (RefinementStep::first_sample on); each is folded into the shown image here, so that the image
// after a step is the average of every sample rendered since the view last changed.
#include <cstdint>

#include "runtime/render/image/image.h"
#include "runtime/render/render_settings.h"
#include "runtime/view/refinement_schedule.h"
#include "runtime/view/render_worker.h"

namespace kdpm {

// Sets s to render only the samples of a full-resolution step that the shown image lacks
// (step.first_sample .. step.spp - 1 of a run of step.sequence_spp), for fold_refinement to fold in.
void render_new_samples(const RefinementStep& step, RenderSettings& s);

// frame := the average of `before` (samples_before samples per pixel) and `frame` (added per
// pixel), each weighted by its samples. Throws std::invalid_argument when the sizes differ.
void fold_samples(const Image& before, std::uint32_t samples_before, Image& frame, std::uint32_t added);

// Folds a finished frame into the shown one when it continues it: the same generation and
// size, and the shown frame holds exactly the samples before the new frame's first. The
// folded frame's post (exposure, tone map) is redone from its new linear image. Returns the
// samples per pixel the frame holds afterwards: its own spp when it does not continue the
// shown one (a fresh frame, or one whose predecessor was never shown).
std::uint32_t fold_refinement(FinishedFrame& frame, const FinishedFrame* shown, std::uint32_t shown_samples);

}  // namespace kdpm
