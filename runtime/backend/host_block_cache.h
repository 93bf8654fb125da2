#pragma once
// Host memory kept from one frame for the next (CpuDevice arrays of a frame backend). A frame
// asks for the same large arrays every time, and fresh ones are fresh pages: the kernel maps and
// zeroes each 4 KiB page at its first touch, which costs a large share of a frame's trace pass.
// Blocks given back are handed out again (the smallest that fits, if at most twice the size
// asked for); trim() frees those that a frame did not take again, so what is kept never exceeds
// one frame's arrays.
#include <cstddef>
#include <mutex>
#include <new>
#include <vector>

namespace kdpm {

class HostBlockCache {
public:
    HostBlockCache() = default;
    HostBlockCache(const HostBlockCache&) = delete;
    HostBlockCache& operator=(const HostBlockCache&) = delete;
    ~HostBlockCache();

    // A block of at least `bytes` (64-byte aligned; contents undefined) and its capacity, which
    // give() must be told.
    void* take(std::size_t bytes, std::size_t& capacity);
    void give(void* block, std::size_t capacity);
    // Frees the kept blocks that were not taken since the last trim.
    void trim();
    // Bytes held in kept blocks (not in use): memory this cache will hand out before asking the
    // system for more.
    std::size_t kept_bytes() const;

private:
    static constexpr std::align_val_t kAlignment{64};
    struct Block {
        void* memory;
        std::size_t capacity;
        bool recent;  // given back since the last trim
    };
    mutable std::mutex mutex_;
    std::vector<Block> kept_;
};

inline HostBlockCache::~HostBlockCache() {
    for (const Block& b : kept_) ::operator delete(b.memory, kAlignment);
}

inline void* HostBlockCache::take(std::size_t bytes, std::size_t& capacity) {
    {
        std::lock_guard lock(mutex_);
        std::size_t best = kept_.size();
        for (std::size_t i = 0; i < kept_.size(); ++i)
            if (kept_[i].capacity >= bytes && kept_[i].capacity / 2 <= bytes &&
                (best == kept_.size() || kept_[i].capacity < kept_[best].capacity))
                best = i;
        if (best != kept_.size()) {
            const Block b = kept_[best];
            kept_[best] = kept_.back();
            kept_.pop_back();
            capacity = b.capacity;
            return b.memory;
        }
    }
    capacity = bytes;
    return ::operator new(bytes, kAlignment);
}

inline void HostBlockCache::give(void* block, std::size_t capacity) {
    std::lock_guard lock(mutex_);
    kept_.push_back(Block{block, capacity, true});
}

inline void HostBlockCache::trim() {
    std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (Block& b : kept_) {
        if (b.recent) {
            b.recent = false;
            kept_[n++] = b;
        } else {
            ::operator delete(b.memory, kAlignment);
        }
    }
    kept_.resize(n);
}

inline std::size_t HostBlockCache::kept_bytes() const {
    std::lock_guard lock(mutex_);
    std::size_t total = 0;
    for (const Block& b : kept_) total += b.capacity;
    return total;
}

}  // namespace kdpm
