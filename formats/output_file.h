#pragma once
// The one output discipline of kdpm (trees, hit files, images, AOVs, screenshots):
//  - the destination is resolved first: symlinks are followed to the file they name, so a write
//    replaces that file and keeps the link; an existing target that is not a regular file
//    (a device such as /dev/null, a FIFO, a folder) is refused, never replaced;
//  - bytes go to a private temporary (mkstemp: O_EXCL, mode 0600 until published) beside the
//    resolved target, named ".NAME.kdpm-tmp-PID-XXXXXX" (NAME shortened to fit NAME_MAX);
//  - every write is checked to the last byte, then fsync, rename, and an fsync of the folder;
//  - a temporary is removed on failure, on SIGINT/SIGTERM/SIGHUP, and (when its writer died
//    without cleaning up, e.g. SIGKILL) by the next write to the same destination.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace kdpm {

// The file a write to `requested` replaces (symlinks followed; it need not exist yet).
std::filesystem::path resolve_output_path(const std::filesystem::path& requested);

// Throws FormatError when `output` resolves to the same file as one of `inputs` (compared by
// device and inode), before any work is done.
void check_output_not_input(const std::filesystem::path& output, std::span<const std::filesystem::path> inputs);

// Everything about an output that can be checked before the work that produces it: a target
// that exists but is not a regular file, a missing folder, an output that is an input.
// Throws FormatError with one line.
void check_output_destination(const std::filesystem::path& output, std::span<const std::filesystem::path> inputs);

// True for names of this writer's temporaries (".NAME.kdpm-tmp-PID-XXXXXX").
bool is_output_temporary_name(const std::string& filename);

class OutputTemp {
public:
    // Resolves `destination`, checks it and creates the temporary. Throws FormatError.
    explicit OutputTemp(const std::filesystem::path& destination);
    ~OutputTemp();  // removes the temporary unless published
    OutputTemp(const OutputTemp&) = delete;
    OutputTemp& operator=(const OutputTemp&) = delete;

    const std::filesystem::path& temp_path() const { return temp_; }
    const std::filesystem::path& target() const { return target_; }

    void write(const void* data, std::size_t size);  // all bytes or FormatError
    // Makes the temporary durable: fsync and close. Needed when another library wrote it by path.
    void finish();
    // Renames the finished temporary over the target and syncs the folder.
    void publish();

private:
    [[noreturn]] void fail(const std::string& what) const;
    std::filesystem::path requested_, target_, temp_;
    int fd_ = -1;
    int slot_ = -1;
    bool finished_ = false, published_ = false;
    unsigned mode_ = 0644;
};

}  // namespace kdpm
