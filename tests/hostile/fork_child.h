#pragma once
// Runs a function in a forked child (for faults that end a process: signals, resource limits,
// crashes) and reports how the child ended.
#include <sys/wait.h>
#include <unistd.h>

#include <functional>

namespace kdpm::test {

struct ChildEnd {
    bool exited = false;
    int exit_code = -1;
    int signal = 0;
};

// `body` returns the child's exit code; an exception ends it with 99.
inline ChildEnd run_in_child(const std::function<int()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        int code = 99;
        try {
            code = body();
        } catch (...) {
        }
        ::_exit(code);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    ChildEnd end;
    end.exited = WIFEXITED(status);
    if (end.exited) end.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
    return end;
}

}  // namespace kdpm::test
