#pragma once
// A block of GPU memory owned by one object (CUDA backend only). Mapped file sections are
// uploaded with one copy each, straight from the mapped pointer.
#include <cstddef>

namespace kdpm {

class DeviceBuffer {
public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(std::size_t bytes);  // uninitialised device memory
    static DeviceBuffer upload(const void* host, std::size_t bytes);
    DeviceBuffer(DeviceBuffer&& o) noexcept;
    DeviceBuffer& operator=(DeviceBuffer&& o) noexcept;
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    ~DeviceBuffer();

    void download(void* host, std::size_t bytes) const;
    std::size_t size() const { return bytes_; }
    template <class T>
    T* as() const { return static_cast<T*>(ptr_); }

private:
    void* ptr_ = nullptr;
    std::size_t bytes_ = 0;
};

}  // namespace kdpm
