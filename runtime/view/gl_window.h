#pragma once
// The viewer's window: GLFW with a legacy (2.1-compatible) OpenGL context, so it also runs on
// Mesa's llvmpipe under Xvfb. Shows one RGB image as a texture, letterboxed, with a Dear ImGui
// interface drawn over it, and collects the input that the interface does not take.
#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace kdpm {

struct KeyPress {
    int key;   // GLFW_KEY_*
    int mods;  // GLFW_MOD_*
};

class GlWindow {
public:
    // Throws std::runtime_error (one line) when no display can be opened.
    GlWindow(int width, int height, const std::string& title);
    ~GlWindow();
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;

    bool should_close() const;
    void request_close();
    void poll();
    void wait(double seconds);  // sleeps until an event or the timeout
    void set_title(const std::string& title);
    void set_clipboard(const std::string& text);

    // Uploads an 8-bit RGB image (row 0 at the top); it is shown from the next draw() on.
    void show(const std::vector<unsigned char>& rgb, int width, int height);
    // Draws the image, then the interface that `ui` builds with ImGui calls (none when empty),
    // and presents. With `capture`, the finished frame is also read back (8-bit RGB, row 0 at
    // the top; its size in capture_width/height) before it is presented.
    void draw(const std::function<void()>& ui, std::vector<unsigned char>* capture = nullptr);
    int capture_width() const { return capture_width_; }
    int capture_height() const { return capture_height_; }

    std::vector<KeyPress> take_key_presses();
    bool key_down(int key) const;
    // Cursor movement since the last call while the left button is held (else zero).
    void take_drag(double& dx, double& dy);

private:
    static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);

    GLFWwindow* window_ = nullptr;
    unsigned texture_ = 0;
    int texture_width_ = 0, texture_height_ = 0;
    int capture_width_ = 0, capture_height_ = 0;
    std::vector<KeyPress> presses_;
    bool dragging_ = false;
    double last_x_ = 0.0, last_y_ = 0.0;
};

}  // namespace kdpm
