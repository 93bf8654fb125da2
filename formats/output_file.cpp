#include "formats/output_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <string>

#include "formats/format_error.h"
#include "formats/temp_registry.h"

namespace kdpm {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTempMarker = ".kdpm-tmp-";
// A stale temporary is removed only when its writer is gone and it is this old, so a writer in
// another PID namespace sharing the folder is not disturbed mid-write.
constexpr std::time_t kStaleSeconds = 60;

fs::path folder_of(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

// ".NAME" cut so that ".NAME.kdpm-tmp-PID-XXXXXX" fits in one file name.
std::string temp_base(const fs::path& target) {
    std::string base(1, '.');  // built by appends: GCC 12 warns falsely on "." + string
    base.append(target.filename().string());
    const std::size_t room = NAME_MAX - std::strlen(kTempMarker) - std::to_string(INT_MAX).size() - 7;
    if (base.size() > room) base.resize(room);
    return base;
}

void remove_stale_temporaries(const fs::path& folder, const std::string& prefix) {
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    const std::time_t now = std::time(nullptr);
    while (const dirent* e = ::readdir(dir)) {
        const std::string name = e->d_name;
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid <= 0 || pid == ::getpid()) continue;
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        const fs::path p = folder / name;
        struct stat st{};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()) continue;
        if (now - st.st_mtime < kStaleSeconds) continue;
        ::unlink(p.c_str());
    }
    ::closedir(dir);
}

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

}  // namespace

fs::path resolve_output_path(const fs::path& requested) {
    fs::path p = requested;
    for (int hop = 0; hop < 40; ++hop) {
        struct stat st{};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
        std::error_code ec;
        const fs::path link = fs::read_symlink(p, ec);
        if (ec) return p;
        p = link.is_absolute() ? link : folder_of(p) / link;
    }
    throw FormatError("cannot write '" + requested.string() + "': too many levels of symbolic links");
}

void check_output_not_input(const fs::path& output, std::span<const fs::path> inputs) {
    struct stat out{};
    if (::stat(output.c_str(), &out) != 0) return;  // a new file cannot be an input
    for (const fs::path& in : inputs) {
        struct stat st{};
        if (::stat(in.c_str(), &st) == 0 && same_file(st, out))
            throw FormatError("refusing to write '" + output.string() + "': it is the input '" + in.string() + "'");
    }
}

void check_output_destination(const fs::path& output, std::span<const fs::path> inputs) {
    const fs::path target = resolve_output_path(output);
    struct stat st{};
    if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw FormatError("cannot write '" + output.string() +
                          "': it exists and is not a regular file (kdpm replaces only regular files)");
    const fs::path folder = folder_of(target);
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw FormatError("cannot write '" + output.string() + "': folder '" + folder.string() + "' does not exist");
    if (::access(folder.c_str(), W_OK) != 0)
        throw FormatError("cannot write '" + output.string() + "': folder '" + folder.string() + "': " +
                          std::strerror(errno));
    check_output_not_input(output, inputs);
}

bool is_output_temporary_name(const std::string& name) {
    const std::size_t at = name.rfind(kTempMarker);
    if (name.empty() || name[0] != '.' || at == std::string::npos) return false;
    const std::string tail = name.substr(at + std::strlen(kTempMarker));  // PID-XXXXXX
    const std::size_t dash = tail.find('-');
    return dash != std::string::npos && dash > 0 && tail.size() == dash + 7 &&
           tail.find_first_not_of("0123456789") == dash;
}

OutputTemp::OutputTemp(const fs::path& destination) : requested_(destination) {
    target_ = resolve_output_path(destination);
    struct stat st{};
    if (::stat(target_.c_str(), &st) == 0) {
        if (!S_ISREG(st.st_mode))
            throw FormatError("cannot write '" + destination.string() +
                              "': it exists and is not a regular file (kdpm replaces only regular files)");
        mode_ = st.st_mode & 07777;
    }
    const fs::path folder = folder_of(target_);
    const std::string prefix = temp_base(target_) + kTempMarker;
    remove_stale_temporaries(folder, prefix);
    std::string name = (folder / (prefix + std::to_string(::getpid()) + "-XXXXXX")).string();
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ < 0) fail("cannot create a temporary file beside it");
    temp_ = name;
    slot_ = register_temporary(name.c_str());
}

OutputTemp::~OutputTemp() {
    if (fd_ >= 0) ::close(fd_);
    if (!published_ && !temp_.empty()) ::unlink(temp_.c_str());
    unregister_temporary(slot_);
}

void OutputTemp::fail(const std::string& what) const {
    const int err = errno;
    throw FormatError("cannot write '" + requested_.string() + "': " + what + ": " + std::strerror(err));
}

void OutputTemp::write(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd_, p, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("write failed");
        }
        if (n == 0) {
            errno = ENOSPC;
            fail("write failed");
        }
        p += n;
        size -= static_cast<std::size_t>(n);
    }
}

void OutputTemp::finish() {
    if (finished_) return;
    if (::fchmod(fd_, static_cast<mode_t>(mode_)) != 0) fail("cannot set its permissions");
    if (::fsync(fd_) != 0) fail("flush failed");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("close failed");
    finished_ = true;
}

void OutputTemp::publish() {
    finish();
    if (::rename(temp_.c_str(), target_.c_str()) != 0) fail("rename failed");
    published_ = true;
    unregister_temporary(slot_);
    slot_ = -1;
    // The rename is durable only once the folder itself is on disk.
    const int dir = ::open(folder_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

}  // namespace kdpm
