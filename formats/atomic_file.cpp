#include "formats/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "formats/format_error.h"

namespace kdpm {
namespace {

struct TempFile {
    std::string path;
    int fd = -1;
    bool keep = false;
    ~TempFile() {
        if (fd >= 0) ::close(fd);
        if (!keep && !path.empty()) ::unlink(path.c_str());
    }
};

[[noreturn]] void fail(const std::filesystem::path& dest, const char* what) {
    throw FormatError("cannot write '" + dest.string() + "': " + what + ": " + std::strerror(errno));
}

}  // namespace

void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const ByteSink&)>& fill) {
    auto dir = destination.parent_path();
    if (dir.empty()) dir = ".";
    TempFile tmp;
    // A hidden name beside the destination, so the rename stays on one file system.
    std::string name = destination.filename().string();
    name.insert(name.begin(), '.');
    name.append(".tmp-XXXXXX");
    tmp.path = (dir / name).string();
    tmp.fd = ::mkstemp(tmp.path.data());
    if (tmp.fd < 0) {
        tmp.path.clear();
        fail(destination, "cannot create a temporary file beside it");
    }
    ::fchmod(tmp.fd, 0644);

    fill([&](const void* data, std::size_t size) {
        const char* p = static_cast<const char*>(data);
        while (size > 0) {
            ssize_t n = ::write(tmp.fd, p, size);
            if (n < 0) {
                if (errno == EINTR) continue;
                fail(destination, "write failed");
            }
            p += n;
            size -= static_cast<std::size_t>(n);
        }
    });

    if (::fsync(tmp.fd) != 0) fail(destination, "flush failed");
    if (::close(tmp.fd) != 0) {
        tmp.fd = -1;
        fail(destination, "close failed");
    }
    tmp.fd = -1;
    if (::rename(tmp.path.c_str(), destination.c_str()) != 0) fail(destination, "rename failed");
    tmp.keep = true;
}

}  // namespace kdpm
