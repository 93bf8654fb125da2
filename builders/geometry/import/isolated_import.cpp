#include "builders/geometry/import/isolated_import.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "builders/geometry/import/mesh_nesting.h"
#include "builders/geometry/import/scene_import.h"
#include "formats/format_error.h"

namespace kdpm {

namespace {

// The scene as the child sends it: a status byte (0: scene, 1: error message), then each
// field as a length and raw bytes. Both ends are this program, so the layout is the memory one.
void put_bytes(std::string& out, const void* data, std::uint64_t size) {
    out.append(reinterpret_cast<const char*>(&size), sizeof size);
    out.append(static_cast<const char*>(data), size);
}
template <class T>
void put_vector(std::string& out, const std::vector<T>& v) {
    put_bytes(out, v.data(), v.size() * sizeof(T));
}

void put_strings(std::string& out, const std::vector<std::string>& v) {
    const std::uint64_t count = v.size();
    put_bytes(out, &count, sizeof count);
    for (const std::string& s : v) put_bytes(out, s.data(), s.size());
}

struct Reader {
    const std::string& in;
    std::size_t at = 1;
    std::string bytes() {
        std::uint64_t size = 0;
        if (in.size() - at < sizeof size) throw FormatError("the mesh importer's reply is cut short");
        std::memcpy(&size, in.data() + at, sizeof size);
        at += sizeof size;
        if (in.size() - at < size) throw FormatError("the mesh importer's reply is cut short");
        std::string s = in.substr(at, size);
        at += size;
        return s;
    }
    template <class T>
    std::vector<T> vector() {
        const std::string s = bytes();
        if (s.size() % sizeof(T) != 0) throw FormatError("the mesh importer's reply is malformed");
        std::vector<T> v(s.size() / sizeof(T));
        if (!s.empty()) std::memcpy(v.data(), s.data(), s.size());
        return v;
    }
    std::vector<std::string> strings() {
        const std::vector<std::uint64_t> count = vector<std::uint64_t>();
        if (count.size() != 1 || count[0] > in.size()) throw FormatError("the mesh importer's reply is malformed");
        std::vector<std::string> v;
        for (std::uint64_t i = 0; i < count[0]; ++i) v.push_back(bytes());
        return v;
    }
};

std::string encode(const Scene& s) {
    std::string out(1, '\0');
    put_vector(out, s.triangles);
    put_vector(out, s.normals);
    put_vector(out, s.materials);
    put_vector(out, s.lights);
    put_vector(out, s.uvs);
    put_strings(out, s.texture_paths);
    put_strings(out, s.warnings);
    put_bytes(out, s.source_name.data(), s.source_name.size());
    put_bytes(out, s.source_hash.data(), s.source_hash.size());
    return out;
}

Scene decode(const std::string& in) {
    Reader r{in};
    Scene s;
    s.triangles = r.vector<TriangleRecord>();
    s.normals = r.vector<TriangleNormals>();
    s.materials = r.vector<MaterialRecord>();
    s.lights = r.vector<AreaLightRecord>();
    s.uvs = r.vector<TriangleUVs>();
    s.texture_paths = r.strings();
    s.warnings = r.strings();
    s.source_name = r.bytes();
    s.source_hash = r.bytes();
    return s;
}

bool write_all(int fd, const std::string& data) {
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

Scene run_isolated(const std::function<Scene()>& import, const std::string& what, unsigned time_limit_s) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw FormatError("cannot start the mesh importer: " + std::string(std::strerror(errno)));
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw FormatError("cannot start the mesh importer: " + std::string(std::strerror(errno)));
    }
    if (pid == 0) {
        ::close(fds[0]);
        // Assimp prints its assertion messages; the parent reports the failure in one line.
        if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, 2);
        // A crash ends the child plainly: handlers inherited from the parent (a sanitizer's, a
        // fuzzer's) would report it as the parent's own.
        for (const int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGALRM}) ::signal(sig, SIG_DFL);
        if (time_limit_s > 0) ::alarm(time_limit_s);
        std::string reply;
        try {
            reply = encode(import());
        } catch (const std::exception& e) {
            reply.assign(1, '\1');
            reply.append(e.what());
        }
        ::_exit(write_all(fds[1], reply) ? 0 : 1);
    }
    ::close(fds[1]);
    std::string reply;
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        reply.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
        throw FormatError(what + ": cannot read mesh: the importer took longer than " + std::to_string(time_limit_s) + " s");
    if (WIFSIGNALED(status))
        throw FormatError(what + ": cannot read mesh: the importer crashed (" + ::strsignal(WTERMSIG(status)) + ")");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty())
        throw FormatError(what + ": cannot read mesh: the importer failed");
    if (reply[0] == '\1') throw FormatError(reply.substr(1));
    return decode(reply);
}

Scene import_mesh_isolated(const std::filesystem::path& path) {
    return run_isolated([&] { return import_mesh(path); }, path.string(), 0);
}

Scene import_mesh_from_memory_isolated(std::string_view bytes, const std::string& extension, const std::string& name,
                                       unsigned time_limit_s) {
    // kdpm's own checks run here, in the caller's process; only Assimp and what reads its
    // result run in the child.
    if (bytes.empty()) throw FormatError(name + ": the mesh file is empty");
    check_mesh_nesting(bytes, extension, name);
    return run_isolated([&] { return import_mesh_from_memory(bytes, extension, name); }, name, time_limit_s);
}

}  // namespace kdpm
