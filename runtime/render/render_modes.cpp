#include "runtime/render/render_modes.h"

#include <stdexcept>

namespace kdpm {

const RenderModeInfo& mode_info(RenderMode mode) {
    for (const RenderModeInfo& m : kRenderModes)
        if (m.mode == mode) return m;
    throw std::invalid_argument("unknown render mode " + std::to_string(static_cast<std::uint32_t>(mode)));
}

namespace {

// "a, b or c" over the rows, each as item(row) gives it.
template <class Item>
std::string joined(Item&& item) {
    std::string text;
    const std::size_t n = std::size(kRenderModes);
    for (std::size_t i = 0; i < n; ++i) {
        if (i) text += i + 1 == n ? " or " : ", ";
        text += item(kRenderModes[i]);
    }
    return text;
}

}  // namespace

std::string render_mode_names() {
    return joined([](const RenderModeInfo& m) { return std::string(m.name); });
}

RenderMode parse_render_mode(std::string_view text) {
    for (const RenderModeInfo& m : kRenderModes)
        if (text == m.name) return m.mode;
    throw std::invalid_argument("expected " + render_mode_names() + ", got '" + std::string(text) + "'");
}

std::string render_mode_help(std::string_view default_text) {
    return joined([](const RenderModeInfo& m) { return std::string(m.name) + " (" + m.help + ")"; }) +
           "; default: " + std::string(default_text);
}

}  // namespace kdpm
