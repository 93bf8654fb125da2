#include "runtime/backend/device_buffer.h"

#include <utility>

#include "runtime/backend/cuda_check.h"

namespace kdpm {

DeviceBuffer::DeviceBuffer(std::size_t bytes) : bytes_(bytes) {
    if (bytes > 0) cuda_check(cudaMalloc(&ptr_, bytes), "cudaMalloc");
}

DeviceBuffer DeviceBuffer::upload(const void* host, std::size_t bytes) {
    DeviceBuffer b(bytes);
    if (bytes > 0) cuda_check(cudaMemcpy(b.ptr_, host, bytes, cudaMemcpyHostToDevice), "upload");
    return b;
}

DeviceBuffer::DeviceBuffer(DeviceBuffer&& o) noexcept
    : ptr_(std::exchange(o.ptr_, nullptr)), bytes_(std::exchange(o.bytes_, 0)) {}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& o) noexcept {
    if (this != &o) {
        if (ptr_) cudaFree(ptr_);
        ptr_ = std::exchange(o.ptr_, nullptr);
        bytes_ = std::exchange(o.bytes_, 0);
    }
    return *this;
}

DeviceBuffer::~DeviceBuffer() {
    if (ptr_) cudaFree(ptr_);
}

void DeviceBuffer::download(void* host, std::size_t bytes) const {
    if (bytes > bytes_) throw std::runtime_error("CUDA: download larger than the buffer");
    if (bytes > 0) cuda_check(cudaMemcpy(host, ptr_, bytes, cudaMemcpyDeviceToHost), "download");
}

}  // namespace kdpm
