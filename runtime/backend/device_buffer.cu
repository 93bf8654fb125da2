#include "runtime/backend/device_buffer.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "runtime/backend/cuda_check.h"

namespace kdpm {

namespace {

std::string mib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

}  // namespace

DeviceBuffer::DeviceBuffer(std::size_t bytes) : bytes_(bytes) {
    if (bytes == 0) return;
    const cudaError_t status = cudaMalloc(&ptr_, bytes);
    if (status != cudaSuccess) {
        ptr_ = nullptr;
        bytes_ = 0;
        cuda_check(status, ("allocating " + mib(bytes) + " of device memory").c_str());
    }
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
