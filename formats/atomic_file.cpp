#include "formats/atomic_file.h"

#include "formats/output_file.h"

namespace kdpm {

void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const ByteSink&)>& fill) {
    OutputTemp temp(destination);
    fill([&](const void* data, std::size_t size) { temp.write(data, size); });
    temp.publish();
}

}  // namespace kdpm
