#pragma once
// Image storage kept from finished frames for the next ones. A 512x512 frame's linear, exposed
// and display images are 3 MiB each, and fresh ones are fresh pages the kernel maps and zeroes
// at first touch, which costs a noticeable share of a viewer frame. A caller done with a frame
// gives its images back (Renderer::recycle); the next frame takes them.
#include <cstddef>
#include <mutex>
#include <vector>

#include "runtime/render/image/image.h"

namespace kdpm {

class ImagePool {
public:
    // A zeroed width x height image, in kept storage when some is large enough.
    Image take(int width, int height);
    // Keeps the image's storage (at most kKept images; beyond that the smallest is freed).
    void give(Image&& image);
    std::size_t kept() const;

private:
    static constexpr std::size_t kKept = 6;  // two frames' three images
    mutable std::mutex mutex_;
    std::vector<std::vector<float>> kept_;
};

}  // namespace kdpm
