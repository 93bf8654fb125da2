#include "runtime/view/control_panel.h"

#include <cfloat>
#include <cmath>
#include <cstdio>

#include <imgui.h>

namespace kdpm {
namespace {

const ViewKind kViews[] = {ViewKind::shaded, ViewKind::depth, ViewKind::normal, ViewKind::photon_density};
const ToneMap kToneMaps[] = {ToneMap::aces, ToneMap::reinhard, ToneMap::none};

ImU32 to_imgui(const glm::vec3& c) {
    return IM_COL32(static_cast<int>(c.r * 255.0f + 0.5f), static_cast<int>(c.g * 255.0f + 0.5f),
                    static_cast<int>(c.b * 255.0f + 0.5f), 255);
}

void density_legend(const DensityScale& scale) {
    ImGui::TextUnformatted("photon density (photons / area)");
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
    const int steps = 64;
    for (int i = 0; i < steps; ++i) {
        const float t0 = static_cast<float>(i) / steps, t1 = static_cast<float>(i + 1) / steps;
        // The bar spans the scale's dark to bright end, as the image maps densities.
        const float log_density = scale.log_lo + (t0 + t1) * 0.5f * (scale.log_hi - scale.log_lo);
        draw->AddRectFilled(ImVec2(origin.x + t0 * width, origin.y), ImVec2(origin.x + t1 * width, origin.y + height),
                            to_imgui(heat_color(density_scale_position(scale, log_density))));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("%.3g", std::exp(scale.log_lo));
    char hi[32];
    std::snprintf(hi, sizeof hi, "%.3g", std::exp(scale.log_hi));
    ImGui::SameLine(width - ImGui::CalcTextSize(hi).x);
    ImGui::TextUnformatted(hi);
}

void timings(const FrameHistory& history) {
    if (history.size() == 0) return;
    struct Row {
        const char* label;
        float (*stage)(const StageSample&);
    };
    const Row rows[] = {{"trace", [](const StageSample& s) { return s.trace_ms; }},
                        {"gather", [](const StageSample& s) { return s.gather_ms; }},
                        {"shade", [](const StageSample& s) { return s.shade_ms; }},
                        {"frame", [](const StageSample& s) { return s.total(); }}};
    for (const Row& row : rows) {
        const std::vector<float> values = history.series(row.stage);
        char overlay[48];
        std::snprintf(overlay, sizeof overlay, "%s %.1f ms", row.label, values.back());
        ImGui::PlotLines(row.label, values.data(), static_cast<int>(values.size()), 0, overlay, 0.0f, FLT_MAX,
                         ImVec2(0, 24));
    }
}

}  // namespace

PanelActions draw_control_panel(const PanelModel& m) {
    PanelActions act;
    ViewOptions& o = *m.options;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.8f);
    if (!ImGui::Begin("kdpm-view (O hides, H keys)")) {
        ImGui::End();
        return act;
    }
    ImGui::TextUnformatted(m.frame_line.c_str());
    ImGui::TextUnformatted(m.photons_line.c_str());
    ImGui::Text("backend: %s", m.backend.c_str());

    if (ImGui::BeginCombo("mode", render_mode_name(o.mode))) {
        for (const RenderModeInfo& info : render_modes()) {
            const RenderMode mode = info.mode;
            const bool usable = m.have_photons || !info.needs_photons;
            if (usable && ImGui::Selectable(render_mode_name(mode), mode == o.mode) && mode != o.mode) {
                o.mode = mode;
                act.rerender = true;
            }
        }
        ImGui::EndCombo();
    }
    int k = static_cast<int>(o.k);
    if (ImGui::SliderInt("k", &k, ViewOptions::kMinK, ViewOptions::kMaxK, "%d", ImGuiSliderFlags_Logarithmic)) {
        o.k = clamp_k(static_cast<std::uint32_t>(k));
        act.rerender = true;
    }
    int spp = static_cast<int>(*m.max_spp);
    if (ImGui::SliderInt("max spp", &spp, 1, 256, "%d", ImGuiSliderFlags_Logarithmic)) {
        *m.max_spp = static_cast<std::uint32_t>(spp < 1 ? 1 : spp);
        act.rerender = true;
    }
    int light = static_cast<int>(*m.light_samples);
    if (ImGui::SliderInt("shadow rays", &light, 1, 256, "%d", ImGuiSliderFlags_Logarithmic)) {
        *m.light_samples = static_cast<std::uint32_t>(light < 1 ? 1 : light);
        act.rerender = true;
    }
    if (ImGui::SliderFloat("exposure", &o.exposure_stops, -16.0f, 16.0f, "%+.1f stops")) act.recompose = true;
    if (ImGui::BeginCombo("tone map", tone_map_name(o.tone_map))) {
        for (ToneMap t : kToneMaps)
            if (ImGui::Selectable(tone_map_name(t), t == o.tone_map)) {
                o.tone_map = t;
                act.recompose = true;
            }
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("view", view_name(o.view))) {
        for (ViewKind v : kViews) {
            if (v == ViewKind::photon_density && !m.have_photons) continue;
            if (ImGui::Selectable(view_name(v), v == o.view) && v != o.view) {
                act.rerender |= view_switch_renders(o.view, v);
                o.view = v;
                act.recompose = true;
            }
        }
        ImGui::EndCombo();
    }
    if (o.view == ViewKind::photon_density && m.density && m.density->valid) density_legend(*m.density);

    if (m.history && ImGui::CollapsingHeader("timings (ms)", ImGuiTreeNodeFlags_DefaultOpen)) timings(*m.history);

    if (ImGui::CollapsingHeader("camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        const CameraRecord& c = m.camera;
        ImGui::Text("eye    %.3f %.3f %.3f", c.eye[0], c.eye[1], c.eye[2]);
        ImGui::Text("lookat %.3f %.3f %.3f", c.lookat[0], c.lookat[1], c.lookat[2]);
        ImGui::Text("vfov   %.1f", c.vfov_degrees);
        if (ImGui::Button("copy as command line")) act.copy_camera = true;
        ImGui::SameLine();
        if (ImGui::Button("reset (R)")) act.reset_camera = true;
    }
    ImGui::End();
    return act;
}

void draw_key_help() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("keys (H closes)", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::TextUnformatted(key_help_text().c_str());
    ImGui::End();
}

}  // namespace kdpm
