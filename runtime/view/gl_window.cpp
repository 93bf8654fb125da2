#include "runtime/view/gl_window.h"

#include <algorithm>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <GL/gl.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

namespace kdpm {

namespace {

std::string& last_glfw_error() {
    static std::string message;
    return message;
}

void remember_error(int, const char* description) { last_glfw_error() = description ? description : "unknown"; }

}  // namespace

GlWindow::GlWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(remember_error);
    if (!glfwInit())
        throw std::runtime_error("no display available (" + last_glfw_error() +
                                 "); set DISPLAY or run under xvfb-run -a");
    // Any context that offers the fixed-function pipeline: 2.1 is enough.
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        std::string why = last_glfw_error();
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 2.1 window (" + why + ")");
    }
    glfwSetWindowUserPointer(window_, this);
    // Installed before ImGui's, which then chains to it.
    glfwSetKeyCallback(window_, on_key);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glGenTextures(1, &texture_);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL2_Init();
}

GlWindow::~GlWindow() {
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    if (texture_) glDeleteTextures(1, &texture_);
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlWindow::poll() { glfwPollEvents(); }
void GlWindow::wait(double seconds) { glfwWaitEventsTimeout(seconds); }
void GlWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
void GlWindow::set_clipboard(const std::string& text) { glfwSetClipboardString(window_, text.c_str()); }

void GlWindow::on_key(GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    // Typing into a widget is not a viewer shortcut.
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
    auto* self = static_cast<GlWindow*>(glfwGetWindowUserPointer(w));
    self->presses_.push_back({key, mods});
}

std::vector<KeyPress> GlWindow::take_key_presses() {
    std::vector<KeyPress> out;
    out.swap(presses_);
    return out;
}

bool GlWindow::key_down(int key) const {
    if (ImGui::GetIO().WantCaptureKeyboard) return false;
    return glfwGetKey(window_, key) == GLFW_PRESS;
}

void GlWindow::take_drag(double& dx, double& dy) {
    dx = dy = 0.0;
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    // A drag that starts on the interface moves a slider, not the camera.
    const bool held = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS &&
                      (dragging_ || !ImGui::GetIO().WantCaptureMouse);
    if (held && dragging_) {
        dx = x - last_x_;
        dy = y - last_y_;
    }
    dragging_ = held;
    last_x_ = x;
    last_y_ = y;
}

void GlWindow::show(const std::vector<unsigned char>& rgb, int width, int height) {
    if (width <= 0 || height <= 0 || rgb.size() < static_cast<std::size_t>(width) * height * 3) return;
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (width != texture_width_ || height != texture_height_) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        texture_width_ = width;
        texture_height_ = height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    }
}

void GlWindow::draw(const std::function<void()>& ui, std::vector<unsigned char>* capture) {
    int fb_width = 0, fb_height = 0;
    glfwGetFramebufferSize(window_, &fb_width, &fb_height);
    glViewport(0, 0, fb_width, fb_height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (texture_width_ > 0 && texture_height_ > 0 && fb_width > 0 && fb_height > 0) {
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, texture_);
        // Letterbox: keep the image's aspect ratio inside the framebuffer.
        const double sx = static_cast<double>(fb_width) / texture_width_;
        const double sy = static_cast<double>(fb_height) / texture_height_;
        const double s = std::min(sx, sy);
        const float hx = static_cast<float>(texture_width_ * s / fb_width);
        const float hy = static_cast<float>(texture_height_ * s / fb_height);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glColor3f(1.0f, 1.0f, 1.0f);
        glBegin(GL_QUADS);  // texture row 0 is the image's top
        glTexCoord2f(0.0f, 1.0f);
        glVertex2f(-hx, -hy);
        glTexCoord2f(1.0f, 1.0f);
        glVertex2f(hx, -hy);
        glTexCoord2f(1.0f, 0.0f);
        glVertex2f(hx, hy);
        glTexCoord2f(0.0f, 0.0f);
        glVertex2f(-hx, hy);
        glEnd();
        glDisable(GL_TEXTURE_2D);
    }
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (ui) ui();
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    if (capture && fb_width > 0 && fb_height > 0) {
        std::vector<unsigned char> rows(static_cast<std::size_t>(fb_width) * fb_height * 3);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, fb_width, fb_height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
        // OpenGL's row 0 is the bottom.
        capture->resize(rows.size());
        const std::size_t stride = static_cast<std::size_t>(fb_width) * 3;
        for (int y = 0; y < fb_height; ++y)
            std::copy_n(&rows[(fb_height - 1 - y) * stride], stride, &(*capture)[y * stride]);
        capture_width_ = fb_width;
        capture_height_ = fb_height;
    }
    glfwSwapBuffers(window_);
}

}  // namespace kdpm
