#pragma once
// The viewer's window: GLFW with a legacy (2.1-compatible) OpenGL context, so it also runs on
// Mesa's llvmpipe under Xvfb. Shows one RGB image as a texture, letterboxed, and collects input.
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

    // Uploads an 8-bit RGB image (row 0 at the top) and presents it.
    void present(const std::vector<unsigned char>& rgb, int width, int height);

    std::vector<KeyPress> take_key_presses();
    bool key_down(int key) const;
    // Cursor movement since the last call while the left button is held (else zero).
    void take_drag(double& dx, double& dy);

private:
    static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);

    GLFWwindow* window_ = nullptr;
    unsigned texture_ = 0;
    int texture_width_ = 0, texture_height_ = 0;
    std::vector<KeyPress> presses_;
    bool dragging_ = false;
    double last_x_ = 0.0, last_y_ = 0.0;
};

}  // namespace kdpm
