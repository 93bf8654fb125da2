#include "runtime/render/image/image_pool.h"

#include <algorithm>
#include <utility>

namespace kdpm {

Image ImagePool::take(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    const std::size_t size = image.pixel_count() * 3;
    {
        std::lock_guard lock(mutex_);
        // The smallest kept storage that holds the image.
        auto best = kept_.end();
        for (auto it = kept_.begin(); it != kept_.end(); ++it)
            if (it->capacity() >= size && (best == kept_.end() || it->capacity() < best->capacity())) best = it;
        if (best != kept_.end()) {
            image.rgb = std::move(*best);
            kept_.erase(best);
        }
    }
    image.rgb.assign(size, 0.0f);
    return image;
}

void ImagePool::give(Image&& image) {
    std::vector<float> storage = std::move(image.rgb);
    image = Image();
    if (storage.capacity() == 0) return;
    std::lock_guard lock(mutex_);
    if (kept_.size() < kKept) {
        kept_.push_back(std::move(storage));
        return;
    }
    auto smallest = std::min_element(kept_.begin(), kept_.end(),
                                     [](const auto& a, const auto& b) { return a.capacity() < b.capacity(); });
    if (smallest->capacity() < storage.capacity()) *smallest = std::move(storage);
}

std::size_t ImagePool::kept() const {
    std::lock_guard lock(mutex_);
    return kept_.size();
}

}  // namespace kdpm
