#include "runtime/view/view_options.h"

#include <algorithm>
#include <stdexcept>

namespace kdpm {

const char* view_name(ViewKind v) {
    switch (v) {
        case ViewKind::shaded: return "shaded";
        case ViewKind::depth: return "depth";
        case ViewKind::normal: return "normal";
        case ViewKind::photon_density: return "photon density";
    }
    return "?";
}

ViewKind parse_view(std::string_view text) {
    if (text == "shaded") return ViewKind::shaded;
    if (text == "depth") return ViewKind::depth;
    if (text == "normal") return ViewKind::normal;
    if (text == "density") return ViewKind::photon_density;
    throw std::invalid_argument("expected shaded, depth, normal or density, got '" + std::string(text) + "'");
}

const char* tone_map_name(ToneMap t) {
    switch (t) {
        case ToneMap::aces: return "aces";
        case ToneMap::reinhard: return "reinhard";
        case ToneMap::none: return "none";
    }
    return "?";
}

std::uint32_t clamp_k(std::uint32_t k) { return std::clamp(k, ViewOptions::kMinK, ViewOptions::kMaxK); }

void ViewOptions::halve_k() { k = clamp_k(k / 2); }
void ViewOptions::double_k() { k = clamp_k(k * 2); }

void ViewOptions::next_mode(bool have_photons) {
    const auto modes = render_modes();
    std::size_t at = 0;
    while (at < modes.size() && modes[at].mode != mode) ++at;
    for (std::size_t step = 1; step <= modes.size(); ++step) {
        const RenderModeInfo& next = modes[(at + step) % modes.size()];
        if (next.in_key_cycle && (have_photons || !next.needs_photons)) {
            mode = next.mode;
            return;
        }
    }
}

AovSet aovs_for_view(ViewKind v) {
    AovSet aovs;
    switch (v) {
        case ViewKind::shaded: break;
        case ViewKind::depth: aovs.depth = true; break;
        case ViewKind::normal: aovs.normal = true; break;
        case ViewKind::photon_density: aovs.position = aovs.normal = true; break;
    }
    return aovs;
}

bool view_switch_renders(ViewKind from, ViewKind to) {
    if ((from == ViewKind::photon_density) != (to == ViewKind::photon_density)) return true;
    return aovs_for_view(from) != aovs_for_view(to);
}

void ViewOptions::next_view(bool have_photons) {
    switch (view) {
        case ViewKind::shaded: view = ViewKind::depth; break;
        case ViewKind::depth: view = ViewKind::normal; break;
        case ViewKind::normal: view = have_photons ? ViewKind::photon_density : ViewKind::shaded; break;
        case ViewKind::photon_density: view = ViewKind::shaded; break;
    }
}

void ViewOptions::next_tone_map() {
    switch (tone_map) {
        case ToneMap::aces: tone_map = ToneMap::reinhard; break;
        case ToneMap::reinhard: tone_map = ToneMap::none; break;
        case ToneMap::none: tone_map = ToneMap::aces; break;
    }
}

std::string key_help_text() {
    std::string cycle, panel;
    for (const RenderModeInfo& m : render_modes()) {
        std::string& list = m.in_key_cycle ? cycle : panel;
        list += (list.empty() ? "" : m.in_key_cycle ? " / " : ", ") + std::string(m.name);
    }
    return "W/A/S/D  move   Q/E  down/up   shift  faster\n"
           "drag     look   R    reset to the file's camera\n"
           "[ ]      halve/double k (" + std::to_string(ViewOptions::kMinK) + ".." + std::to_string(ViewOptions::kMaxK) + ")\n"
           "M        mode: " + cycle + " (" + panel + ": in the panel)\n"
           "V        view: shaded / depth / normal / photon density\n"
           "+ -      exposure   T  tone mapper\n"
           "F12      screenshot (PNG in the working folder)\n"
           "H        help       O  panel   Esc  quit";
}

}  // namespace kdpm
