// kdpm-view's main loop: input -> fly camera and view options -> frame jobs for the background
// render worker -> the newest useful frame composed and presented under the control panel.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "runtime/render/default_mode.h"
#include "runtime/render/frame_memory.h"
#include "runtime/render/image/image_output.h"
#include "runtime/render/image_size.h"
#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "runtime/view/camera_command_line.h"
#include "runtime/view/control_panel.h"
#include "runtime/view/fly_camera.h"
#include "runtime/view/frame_composer.h"
#include "runtime/view/gl_window.h"
#include "runtime/view/refinement_folding.h"
#include "runtime/view/refinement_schedule.h"
#include "runtime/view/render_worker.h"
#include "runtime/view/screenshot_name.h"
#include "runtime/view/viewer_config.h"
#include "runtime/view/viewer_memory.h"

namespace kdpm {

namespace {

using Clock = std::chrono::steady_clock;


class Viewer {
public:
    Viewer(const ViewerConfig& cfg, const LoadedScene& scene, const CameraRecord& start_camera, Renderer& renderer,
           GlWindow& window)
        : cfg_(cfg), renderer_(renderer), window_(window),
          camera_(start_camera, scene.views().geometry.info), worker_(renderer),
          schedule_(1, 1, cfg.max_spp, cfg.preview_divisor), max_spp_(cfg.max_spp), light_samples_(cfg.light_samples) {
        const ImageSize size = image_size(cfg.width, cfg.height, start_camera);
        width_ = size.width;
        height_ = size.height;
        schedule_ = RefinementSchedule(width_, height_, max_spp_, cfg.preview_divisor);
        have_photons_ = !scene.views().photons.empty();
        photons_ = scene.views().photons;
        const std::uint32_t scene_k = scene.views().geometry.info.default_k;
        options_.k = clamp_k(cfg.k ? cfg.k : (scene_k ? scene_k : 100));
        options_.mode = cfg.mode ? *cfg.mode : default_render_mode(scene.views());
        options_.view = cfg.view;
        options_.exposure_stops = cfg.exposure_stops;
        options_.tone_map = cfg.tone_map;
        plain_ = Image(static_cast<int>(width_), static_cast<int>(height_));
    }

    int run_interactive() {
        restart(true);
        auto last = Clock::now();
        while (!window_.should_close()) {
            window_.poll();
            const auto now = Clock::now();
            const float dt = std::min(0.1f, std::chrono::duration<float>(now - last).count());
            last = now;
            bool view_changed = false, camera_changed = false;
            handle_keys(view_changed, camera_changed);
            apply_panel_actions(view_changed, camera_changed);
            camera_changed |= fly(dt);
            if (camera_changed || view_changed) restart(true);
            bool fresh = collect_frame();
            if (fresh || recompose_) compose();
            // The interface is redrawn every pass, so its widgets answer at once.
            window_.draw(ui(true));
            // Sleep while nothing is moving; stay responsive to keys, the panel and the worker.
            if (!camera_changed && !fresh) window_.wait(1.0 / 60.0);
        }
        return 0;
    }

    int run_scripted() {
        if (!cfg_.quiet) std::printf("%s\n", key_help_text().c_str());
        // Fly: hold W while the mouse sways the view gently right and back left (one full sway
        // over the flight, so the path ends facing the way it started), one preview per 1/30 s.
        for (int i = 0; i < cfg_.fly_frames && !window_.should_close(); ++i) {
            FlyInput in;
            in.forward = 1.0f;
            camera_.move(in, 1.0f / 30.0f);
            const float phase = 6.2831853f * static_cast<float>(i) / static_cast<float>(cfg_.fly_frames);
            camera_.look(2.0f * std::cos(phase), 0.0f);
            schedule_.restart(true);
            render_and_show_blocking(/*refine=*/false);
        }
        schedule_.restart(false);
        for (int i = 0; i < cfg_.frames && !window_.should_close(); ++i) render_and_show_blocking(true);
        if (!cfg_.screenshot.empty()) save(cfg_.screenshot);
        return 0;
    }

private:
    // A new generation makes every queued or in-flight frame stale.
    void restart(bool preview) {
        ++generation_;
        schedule_.restart(preview);
        submit_current();
    }

    FrameJob job_for(const RefinementStep& step) const {
        FrameJob job;
        job.generation = generation_;
        job.preview = step.preview;
        RenderSettings& s = job.settings;
        s.width = step.width;
        s.height = step.height;
        s.spp = step.spp;
        s.passes = step.spp;  // sppm refines by passes: 1, 2, 4, ... while the camera is still
        s.keep_irradiance_cache = true;  // final-gather: records made in earlier frames serve later ones
        s.k = options_.k;
        s.mode = options_.mode;
        s.light_samples = light_samples_;
        if (options_.view == ViewKind::photon_density) {
            // The density comes from a k-nearest search at each pixel's first hit; the frame
            // itself only has to supply the hit points, so it is rendered as cheaply as possible.
            s.mode = RenderMode::direct;
            s.light_samples = 1;
            job.density_k = options_.k;
        } else if (s.mode != RenderMode::sppm) {
            // Only the samples the shown image lacks, folded into it when the frame arrives
            // (sppm's passes refine state of their own; the density view's frames are fresh).
            render_new_samples(step, s);
        }
        s.camera = camera_.record();
        s.camera->width = width_;
        s.camera->height = height_;
        s.aovs = aovs_for_view(options_.view);
        s.post.exposure_stops = options_.exposure_stops;
        s.post.tone_map = options_.tone_map;
        return job;
    }

    void submit_current() {
        if (auto step = schedule_.current()) worker_.submit(job_for(*step));
    }

    // Takes a finished frame from the worker; true when it became the displayed frame.
    bool collect_frame() {
        std::optional<FinishedFrame> done = worker_.take();
        if (!done) return false;
        if (!done->error.empty()) {
            std::fprintf(stderr, "kdpm-view: %s\n", done->error.c_str());
            return false;
        }
        const bool current = done->job.generation == generation_;
        // A stale preview is still the newest picture while the camera keeps moving; a stale
        // refinement frame is not shown.
        const bool newer_preview = done->job.preview && done->job.generation > shown_generation_;
        if (!current && !newer_preview) return false;
        accept(std::move(*done));
        if (current) {
            schedule_.advance();
            submit_current();
        }
        return true;
    }

    void accept(FinishedFrame frame) {
        shown_generation_ = frame.job.generation;
        const StageTimes& t = frame.result.times;
        history_.push({static_cast<float>(t.ray_tracing_ms), static_cast<float>(t.photon_gather_ms + frame.density_ms),
                       static_cast<float>(t.shading_ms), static_cast<float>(t.post_ms + t.transfer_ms)});
        shown_samples_ = fold_refinement(frame, last_ ? &*last_ : nullptr, shown_samples_);
        if (last_) renderer_.recycle(std::move(last_->result));
        last_ = std::move(frame);
        recompose_ = true;
    }

    void render_and_show_blocking(bool refine) {
        // Past the cap (scripted runs with more frames than steps): one fresh render at the cap.
        RefinementStep step = schedule_.current().value_or(
            RefinementStep{width_, height_, schedule_.max_spp(), 0, schedule_.max_spp(), false});
        // A new view each time, but a refinement's steps are one view: their frames fold together.
        if (!refine || step.first_sample == 0) ++generation_;
        worker_.submit(job_for(step));
        FinishedFrame done = worker_.wait();
        if (!done.error.empty()) throw std::runtime_error(done.error);
        accept(std::move(done));
        if (refine) schedule_.advance();
        window_.poll();
        compose();
        window_.draw(ui(cfg_.panel));
        if (!cfg_.quiet) std::printf("%s\n", title_text().c_str());
    }

    bool fly(float dt) {
        FlyInput in;
        in.forward = float(window_.key_down(GLFW_KEY_W)) - float(window_.key_down(GLFW_KEY_S));
        in.right = float(window_.key_down(GLFW_KEY_D)) - float(window_.key_down(GLFW_KEY_A));
        in.up = float(window_.key_down(GLFW_KEY_E)) - float(window_.key_down(GLFW_KEY_Q));
        in.fast = window_.key_down(GLFW_KEY_LEFT_SHIFT) || window_.key_down(GLFW_KEY_RIGHT_SHIFT);
        bool moved = camera_.move(in, dt);
        double dx = 0, dy = 0;
        window_.take_drag(dx, dy);
        moved |= camera_.look(static_cast<float>(dx), static_cast<float>(dy));
        return moved;
    }

    void handle_keys(bool& view_changed, bool& camera_changed) {
        for (const KeyPress& k : window_.take_key_presses()) {
            const ViewKind old_view = options_.view;
            switch (k.key) {
                case GLFW_KEY_ESCAPE: window_.request_close(); break;
                case GLFW_KEY_R: camera_.reset(); camera_changed = true; break;
                case GLFW_KEY_LEFT_BRACKET: options_.halve_k(); view_changed = true; break;
                case GLFW_KEY_RIGHT_BRACKET: options_.double_k(); view_changed = true; break;
                case GLFW_KEY_M: options_.next_mode(have_photons_); view_changed = true; break;
                case GLFW_KEY_V: options_.next_view(have_photons_); break;
                case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: options_.brighter(); break;
                case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: options_.darker(); break;
                case GLFW_KEY_T: options_.next_tone_map(); break;
                case GLFW_KEY_H: options_.help = !options_.help; break;
                case GLFW_KEY_O: options_.stats = !options_.stats; break;  // the panel
                case GLFW_KEY_F12: save_unique(); break;
                default: break;
            }
            if (view_switch_renders(old_view, options_.view)) view_changed = true;
            recompose_ = true;
        }
    }

    std::string title_text() const {
        std::ostringstream t;
        t << "kdpm-view: " << std::filesystem::path(cfg_.geometry_path).filename().string() << " | "
          << backend_name(renderer_.backend());
        char line[160];
        if (last_) {
            const auto& r = last_->result;
            const StageTimes& s = r.times;
            std::snprintf(line, sizeof line, " %dx%d %u spp | trace %.0f gather %.0f shade %.0f post %.0f ms",
                          r.linear.width, r.linear.height, shown_samples_, s.ray_tracing_ms,
                          s.photon_gather_ms + last_->density_ms, s.shading_ms, s.post_ms + s.transfer_ms);
            t << line;
        }
        t << " | k " << options_.k << " " << render_mode_name(options_.mode);
        if (have_photons_) t << " | " << photons_.global.photon_count + photons_.caustic.photon_count << " photons";
        t << " | " << view_name(options_.view);
        return t.str();
    }

    // The frame's line in the panel: backend, resolution, samples.
    std::string frame_line() const {
        if (!last_) return "rendering the first frame...";
        char line[160];
        const auto& r = last_->result;
        std::snprintf(line, sizeof line, "%dx%d%s, %u spp", r.linear.width, r.linear.height,
                      last_->job.preview ? " (moving)" : "", shown_samples_);
        return line;
    }

    std::string photons_line() const {
        if (!have_photons_) return "no photon map";
        char line[200];
        // Final gathering falls back to k-nearest estimates at its gather hits without the map.
        std::snprintf(line, sizeof line, "%u global + %u caustic photons, %s", photons_.global.photon_count,
                      photons_.caustic.photon_count,
                      photons_.irradiance.present() ? "irradiance precomputed" : "no precomputed irradiance");
        return line;
    }

    // The interface of this pass: the panel (O toggles it) and the key list (H).
    std::function<void()> ui(bool with_panel) {
        if (!with_panel) return {};
        return [this] {
            if (options_.stats) {
                PanelModel model;
                model.options = &options_;
                model.max_spp = &max_spp_;
                model.light_samples = &light_samples_;
                model.have_photons = have_photons_;
                model.backend = backend_name(renderer_.backend());
                model.frame_line = frame_line();
                model.photons_line = photons_line();
                model.history = &history_;
                model.camera = camera_.record();
                if (options_.view == ViewKind::photon_density && last_) model.density = density_scale(last_->density);
                const PanelActions act = draw_control_panel(model);
                pending_.rerender |= act.rerender;
                pending_.recompose |= act.recompose;
                pending_.reset_camera |= act.reset_camera;
                pending_.copy_camera |= act.copy_camera;
            }
            if (options_.help) draw_key_help();
        };
    }

    void apply_panel_actions(bool& view_changed, bool& camera_changed) {
        const PanelActions act = pending_;
        pending_ = PanelActions{};
        if (act.rerender) {
            schedule_ = RefinementSchedule(width_, height_, max_spp_, cfg_.preview_divisor);
            view_changed = true;
        }
        if (act.reset_camera) {
            camera_.reset();
            camera_changed = true;
        }
        if (act.copy_camera) {
            const std::string line = "kdpm-render " + cfg_.geometry_path +
                                     (cfg_.photon_path.empty() ? "" : " " + cfg_.photon_path) + " " +
                                     camera_command_line(camera_.record());
            std::printf("%s\n", line.c_str());
            std::fflush(stdout);
            window_.set_clipboard(line);
        }
        recompose_ |= act.recompose || act.rerender;
    }

    // Recomposes the view at full size and uploads it.
    void compose() {
        if (last_) plain_ = resize_nearest(compose_view(last_->result, last_->density, options_), int(width_), int(height_));
        to_rgb8(plain_, bytes_);
        window_.show(bytes_, plain_.width, plain_.height);
        window_.set_title(title_text());
        recompose_ = false;
    }

    void save(const std::filesystem::path& path) {
        Image shown;
        if (cfg_.panel) {
            // The window as it looks, panel included: drawn once more and read back.
            std::vector<unsigned char> rgb;
            window_.draw(ui(true), &rgb);
            shown = Image(window_.capture_width(), window_.capture_height());
            for (std::size_t i = 0; i < rgb.size() && i < shown.rgb.size(); ++i) shown.rgb[i] = rgb[i] / 255.0f;
        }
        const Image& img = cfg_.panel ? shown : plain_;
        if (img.pixel_count() == 0) throw std::runtime_error("no frame was rendered, nothing to save");
        FrameOutput out{&img, &img, nullptr, AovSet{}};
        write_frame(path, out);
        if (!cfg_.quiet) std::printf("kdpm-view: saved %s\n", path.string().c_str());
    }

    void save_unique() {
        try {
            save(unique_screenshot_name(std::filesystem::current_path()));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "kdpm-view: %s\n", e.what());
        }
    }

    const ViewerConfig& cfg_;
    Renderer& renderer_;
    GlWindow& window_;
    FlyCamera camera_;
    RenderWorker worker_;
    RefinementSchedule schedule_;
    ViewOptions options_;
    std::uint32_t width_ = 0, height_ = 0;
    bool have_photons_ = false;
    PhotonMaps photons_;
    std::uint64_t generation_ = 0, shown_generation_ = 0;
    std::optional<FinishedFrame> last_;
    std::uint32_t shown_samples_ = 0;  // samples per pixel in last_ (several frames of a refinement, folded)
    Image plain_;
    std::uint32_t max_spp_, light_samples_;
    FrameHistory history_;
    PanelActions pending_;
    std::vector<unsigned char> bytes_;
    bool recompose_ = false;
};

}  // namespace

int run_viewer(const ViewerConfig& cfg) {
    // Input is checked, and the window opened, before anything else is printed, so that a bad
    // file or a missing display is the only line of output.
    std::optional<std::filesystem::path> photons;
    if (!cfg.photon_path.empty()) photons = cfg.photon_path;
    LoadedScene scene = LoadedScene::load(cfg.geometry_path, photons);
    if (cfg.mode && mode_needs_photons(*cfg.mode) && scene.views().photons.empty())
        throw std::runtime_error(std::string("mode ") + render_mode_name(*cfg.mode) +
                                 " needs a photon map (.kdp); give one or use --mode direct");
    if (cfg.view == ViewKind::photon_density && scene.views().photons.empty())
        throw std::runtime_error("the density view needs a photon map (.kdp)");
    const CameraRecord start_camera = cfg.camera.applied_to(scene.views().camera);
    const auto [w, h] = image_size(cfg.width, cfg.height, start_camera);
    check_frame_memory(w, h, viewer_memory_bytes(w, h, !scene.views().photons.empty()), available_memory_bytes());
    GlWindow window(static_cast<int>(w), static_cast<int>(h), "kdpm-view");
    BackendSelection selected = select_backend(cfg.backend);
    if (!selected.notice.empty() && !cfg.quiet) std::fprintf(stderr, "kdpm-view: %s\n", selected.notice.c_str());
    Renderer renderer(scene.views(), selected.kind);
    Viewer viewer(cfg, scene, start_camera, renderer, window);
    const bool scripted = cfg.frames > 0 || cfg.fly_frames > 0 || !cfg.screenshot.empty();
    if (scripted) return viewer.run_scripted();
    if (!cfg.quiet) std::printf("kdpm-view keys:\n%s\n", key_help_text().c_str());
    return viewer.run_interactive();
}

}  // namespace kdpm
