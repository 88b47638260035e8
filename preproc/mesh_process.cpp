// SPDX-License-Identifier: MIT
#include "mesh_process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "core/error.hpp"

namespace gsph::preproc {
namespace {

// The child's answer: one tag, then the payload (a mesh and its warnings, or an error).
enum class Answer : std::uint8_t { Mesh = 1, InputError, MeshError, IoError, OtherError };

// Sent as raw bytes: trivially copyable types, and Eigen's fixed vectors (packed doubles).
template <class T>
constexpr bool kRawBytes = std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec3>;
static_assert(sizeof(Vec3) == 3 * sizeof(double));

// Byte stream of plain values, strings and vectors of trivially copyable elements.
class Writer {
  public:
    template <class T>
    void value(const T& v) {
        static_assert(kRawBytes<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void text(const std::string& s) {
        value<std::uint64_t>(s.size());
        bytes_.append(s);
    }
    template <class T>
    void array(const std::vector<T>& v) {
        static_assert(kRawBytes<T>);
        value<std::uint64_t>(v.size());
        bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    const std::string& bytes() const { return bytes_; }

  private:
    std::string bytes_;
};

class Reader {
  public:
    Reader(const std::string& bytes, const std::string& source) : bytes_(bytes), source_(source) {}
    template <class T>
    T value() {
        T v;
        take(&v, sizeof v);
        return v;
    }
    std::string text() {
        std::string s(count(1), '\0');
        take(s.data(), s.size());
        return s;
    }
    template <class T>
    std::vector<T> array() {
        std::vector<T> v(count(sizeof(T)));
        take(v.data(), v.size() * sizeof(T));
        return v;
    }

  private:
    std::size_t count(std::size_t elementSize) {
        const auto n = value<std::uint64_t>();
        if (n > (bytes_.size() - at_) / elementSize) truncated();
        return static_cast<std::size_t>(n);
    }
    void take(void* to, std::size_t n) {
        if (n > bytes_.size() - at_) truncated();
        if (n > 0) std::memcpy(to, bytes_.data() + at_, n);
        at_ += n;
    }
    [[noreturn]] void truncated() const {
        throw MeshError(source_ + ": the meshing process sent a truncated answer");
    }
    const std::string& bytes_;
    const std::string& source_;
    std::size_t at_ = 0;
};

void writeMesh(Writer& w, const HexMesh& m, const std::vector<std::string>& warnings) {
    w.text(m.source);
    w.array(m.nodes);
    w.array(m.hexes);
    w.array(m.hexTags);
    w.array(m.volumes);
    w.value<std::uint64_t>(m.volumeGroups.size());
    for (const VolumeGroup& g : m.volumeGroups) {
        w.value(g.tag);
        w.text(g.name);
        w.array(g.volumes);
    }
    w.value<std::uint64_t>(m.surfaceGroups.size());
    for (const SurfaceGroup& g : m.surfaceGroups) {
        w.value(g.tag);
        w.text(g.name);
        w.array(g.quads);
    }
    w.value<std::uint64_t>(warnings.size());
    for (const std::string& s : warnings) w.text(s);
}

HexMesh readMesh(Reader& r, std::vector<std::string>& warnings) {
    HexMesh m;
    m.source = r.text();
    m.nodes = r.array<Vec3>();
    m.hexes = r.array<std::array<Index, 8>>();
    m.hexTags = r.array<std::size_t>();
    m.volumes = r.array<HexVolume>();
    m.volumeGroups.resize(r.value<std::uint64_t>());
    for (VolumeGroup& g : m.volumeGroups) {
        g.tag = r.value<int>();
        g.name = r.text();
        g.volumes = r.array<int>();
    }
    m.surfaceGroups.resize(r.value<std::uint64_t>());
    for (SurfaceGroup& g : m.surfaceGroups) {
        g.tag = r.value<int>();
        g.name = r.text();
        g.quads = r.array<std::array<Index, 4>>();
    }
    const auto n = r.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) warnings.push_back(r.text());
    return m;
}

// Writes all bytes to a descriptor; false if the reader went away.
bool writeAll(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

[[noreturn]] void runChild(int fd, const std::filesystem::path& input,
                           const MeshReadOptions& options) {
    Writer w;
    try {
        std::vector<std::string> warnings;
        const HexMesh mesh = readHexMesh(input, options, warnings);
        w.value(Answer::Mesh);
        writeMesh(w, mesh, warnings);
    } catch (const InputError& e) {
        w.value(Answer::InputError);
        w.text(e.what());
    } catch (const MeshError& e) {
        w.value(Answer::MeshError);
        w.text(e.what());
    } catch (const IoError& e) {
        w.value(Answer::IoError);
        w.text(e.what());
    } catch (const std::exception& e) {
        w.value(Answer::OtherError);
        w.text(e.what());
    }
    const bool sent = writeAll(fd, w.bytes());
    ::close(fd);
    ::_exit(sent ? 0 : 1);  // no atexit handlers, no destructors of the parent's objects
}

std::string signalText(int signal) {
    const char* name = ::strsignal(signal);
    return "signal " + std::to_string(signal) + (name ? std::string(", ") + name : "");
}

}  // namespace

HexMesh readHexMeshInChild(const std::filesystem::path& input, const MeshReadOptions& options,
                           std::vector<std::string>& warnings) {
    const std::string source = input.string();
    int fds[2];
    if (::pipe(fds) != 0)
        throw IoError(source + ": cannot open a pipe to the meshing process (" +
                      std::strerror(errno) + ")");
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw IoError(source + ": cannot start the meshing process (" + std::strerror(error) + ")");
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(fds[1], input, options);
    }
    ::close(fds[1]);
    std::string bytes;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status))
        throw MeshError(source + ": gmsh crashed while reading or meshing it (" +
                        signalText(WTERMSIG(status)) +
                        "); check the file and its parameters (a zero or negative grading or "
                        "cell count is a common cause)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
        throw MeshError(source + ": the meshing process ended without an answer (exit status " +
                        std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
    Reader r(bytes, source);
    const auto answer = r.value<Answer>();
    if (answer == Answer::Mesh) return readMesh(r, warnings);
    const std::string what = r.text();
    if (answer == Answer::InputError) throw InputError(what);
    if (answer == Answer::MeshError) throw MeshError(what);
    if (answer == Answer::IoError) throw IoError(what);
    throw Error(what);
}

}  // namespace gsph::preproc
