#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>
#include <string>

#include "runtime/render/render_modes.h"

using namespace kdpm;

TEST_CASE("every render mode parses back from its name, and names are unique", "[render][modes]") {
    std::set<std::string> names;
    for (const RenderModeInfo& m : render_modes()) {
        CHECK(parse_render_mode(m.name) == m.mode);
        CHECK(std::string(render_mode_name(m.mode)) == m.name);
        CHECK(&mode_info(m.mode) == &m);
        CHECK(names.insert(m.name).second);
        CHECK(render_mode_help("x").find(m.name) != std::string::npos);
    }
    CHECK(names.size() == std::size(kRenderModes));
}

TEST_CASE("an unknown mode is refused with the list of the known ones", "[render][modes]") {
    try {
        parse_render_mode("albedo?");
        FAIL("parsed an unknown mode");
    } catch (const std::invalid_argument& e) {
        const std::string text = e.what();
        CHECK(text.find("'albedo?'") != std::string::npos);
        for (const RenderModeInfo& m : render_modes()) CHECK(text.find(m.name) != std::string::npos);
    }
    CHECK(render_mode_names().find("photons, direct+photons, direct, path, sppm") == 0);
}

TEST_CASE("the modes that read a photon map, and those lit only by photons", "[render][modes]") {
    CHECK(mode_needs_photons(RenderMode::photons));
    CHECK(mode_needs_photons(RenderMode::direct_photons));
    CHECK(mode_needs_photons(RenderMode::final_gather));
    CHECK_FALSE(mode_needs_photons(RenderMode::direct));
    CHECK_FALSE(mode_needs_photons(RenderMode::path));
    CHECK_FALSE(mode_needs_photons(RenderMode::sppm));
    CHECK_FALSE(mode_info(RenderMode::photons).direct_light);
    for (RenderMode m : {RenderMode::direct_photons, RenderMode::direct, RenderMode::path, RenderMode::sppm,
                         RenderMode::final_gather})
        CHECK(mode_info(m).direct_light);
    // The modes with a gather and a shade pass keep the trace pass's diffuse vertices.
    for (RenderMode m : {RenderMode::photons, RenderMode::direct_photons, RenderMode::direct, RenderMode::final_gather})
        CHECK(mode_info(m).diffuse_vertices);
    CHECK_FALSE(mode_info(RenderMode::path).diffuse_vertices);
    CHECK_FALSE(mode_info(RenderMode::sppm).diffuse_vertices);
}
