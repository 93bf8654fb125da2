#include "formats/mapped_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <string>
#include <utility>

#include "formats/format_error.h"
#include "formats/temp_registry.h"

namespace kdpm {

namespace {

// A mapped file that another process truncates or replaces in place turns the next read of a
// lost page into SIGBUS. That cannot be recovered inside a kernel loop, so it becomes a one-line
// error and exit code 1 (temporaries of pending outputs are removed first).
extern "C" void mapped_file_lost(int) {
    static const char msg[] = "kdpm: error: an input file was truncated or changed while in use (SIGBUS)\n";
    remove_registered_temporaries();
    [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
    ::_exit(1);
}

void install_sigbus_handler_once() {
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction act{};
        act.sa_handler = mapped_file_lost;
        sigemptyset(&act.sa_mask);
        ::sigaction(SIGBUS, &act, nullptr);
    });
}

}  // namespace

MappedFile::MappedFile(const std::filesystem::path& path) {
    // Non-blocking: opening a FIFO must not wait for a writer before the regular-file check.
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw FormatError("cannot open '" + path.string() + "': " + std::strerror(errno));
    struct stat st{};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw FormatError("'" + path.string() + "' is not a regular file");
    }
    size_ = static_cast<std::size_t>(st.st_size);
    if (size_ > 0) {
        void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
        if (p == MAP_FAILED) {
            int err = errno;
            ::close(fd);
            throw FormatError("cannot map '" + path.string() + "': " + std::strerror(err));
        }
        data_ = static_cast<const std::uint8_t*>(p);
        install_sigbus_handler_once();
    }
    ::close(fd);
}

MappedFile::MappedFile(MappedFile&& o) noexcept
    : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& o) noexcept {
    if (this != &o) {
        this->~MappedFile();
        data_ = std::exchange(o.data_, nullptr);
        size_ = std::exchange(o.size_, 0);
    }
    return *this;
}

MappedFile::~MappedFile() {
    if (data_) ::munmap(const_cast<std::uint8_t*>(data_), size_);
}

}  // namespace kdpm
