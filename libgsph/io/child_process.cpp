// SPDX-License-Identifier: MIT
#include "io/child_process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

namespace gsph {
namespace {

// The child's answer: one tag, then the payload (the work's bytes, or an error's message).
enum class Answer : std::uint8_t { Result = 1, InputError, MeshError, IoError, OtherError };

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

[[noreturn]] void runChild(int fd, const std::function<void(ByteWriter&)>& work) {
    std::string answer;
    try {
        ByteWriter w;
        work(w);
        answer.push_back(static_cast<char>(Answer::Result));
        answer.append(w.bytes());
    } catch (const std::exception& e) {
        const Answer tag = dynamic_cast<const InputError*>(&e)  ? Answer::InputError
                           : dynamic_cast<const MeshError*>(&e) ? Answer::MeshError
                           : dynamic_cast<const IoError*>(&e)   ? Answer::IoError
                                                                : Answer::OtherError;
        answer.assign(1, static_cast<char>(tag));
        answer.append(e.what());
    }
    const bool sent = writeAll(fd, answer);
    ::close(fd);
    ::_exit(sent ? 0 : 1);  // no atexit handlers, no destructors of the parent's objects
}

}  // namespace

unsigned fileReadDeadline(const std::filesystem::path& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    return 60u + (ec ? 0u : static_cast<unsigned>(size / 20000000u));
}

std::string runInChild(const std::string& source, const std::string& what,
                       const std::function<void(ByteWriter&)>& work,
                       const std::function<void(const std::string& reason)>& crashed,
                       unsigned timeoutSeconds) {
    int fds[2];
    if (::pipe(fds) != 0)
        throw IoError(source + ": cannot open a pipe to the " + what + " process (" +
                      std::strerror(errno) + ")");
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw IoError(source + ": cannot start the " + what + " process (" + std::strerror(error) +
                      ")");
    }
    if (pid == 0) {
        ::close(fds[0]);
        // A fault or the deadline ends the child by its signal, whatever handlers the parent
        // installed (a crash reporter, a sanitizer, a fuzzer): the parent reads the signal.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) ::signal(sig, SIG_DFL);
        if (timeoutSeconds > 0) ::alarm(timeoutSeconds);
        runChild(fds[1], work);
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
    std::string reason;
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        const char* name = ::strsignal(signal);
        reason = "signal " + std::to_string(signal) + (name ? std::string(", ") + name : "");
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty()) {
        reason = "it ended without an answer, exit status " +
                 std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    }
    if (!reason.empty()) {
        if (crashed) crashed(reason);
        throw Error(source + ": " + what + " crashed (" + reason + ")");
    }
    const auto tag = static_cast<Answer>(bytes[0]);
    if (tag == Answer::Result) return bytes.substr(1);
    const std::string message = bytes.substr(1);
    if (tag == Answer::InputError) throw InputError(message);
    if (tag == Answer::MeshError) throw MeshError(message);
    if (tag == Answer::IoError) throw IoError(message);
    throw Error(message);
}

}  // namespace gsph
