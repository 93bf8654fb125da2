#include "formats/temp_registry.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace kdpm {

namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};

constexpr int kSlots = 64;
Slot g_slots[kSlots];
// SIGXFSZ: a file-size limit reached while writing ends the process, but not with a temporary left.
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

struct sigaction g_previous[NSIG];

extern "C" void remove_temporaries_and_reraise(int sig) {
    remove_registered_temporaries();
    ::sigaction(sig, &g_previous[sig], nullptr);
    ::raise(sig);  // delivered to the previous disposition once this handler returns
}

// Installs (again, e.g. after a fork or a test framework's own handler) wherever the signal is
// neither ignored nor already ours; the previous disposition gets the signal afterwards.
void install_handlers() {
    static std::mutex m;
    std::lock_guard<std::mutex> lock(m);
    for (int sig : kSignals) {
        struct sigaction old{};
        if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN ||
            old.sa_handler == remove_temporaries_and_reraise)
            continue;
        g_previous[sig] = old;
        struct sigaction act{};
        act.sa_handler = remove_temporaries_and_reraise;
        sigemptyset(&act.sa_mask);
        ::sigaction(sig, &act, nullptr);
    }
}

}  // namespace

void remove_registered_temporaries() {
    for (Slot& s : g_slots)
        if (s.state.load(std::memory_order_acquire) == kReady) ::unlink(s.path);
}

int register_temporary(const char* path) {
    if (std::strlen(path) >= PATH_MAX) return -1;
    install_handlers();
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (g_slots[i].state.compare_exchange_strong(expected, kFilling)) {
            std::strcpy(g_slots[i].path, path);
            g_slots[i].state.store(kReady, std::memory_order_release);
            return i;
        }
    }
    return -1;
}

void unregister_temporary(int slot) {
    if (slot >= 0 && slot < kSlots) g_slots[slot].state.store(kFree, std::memory_order_release);
}

}  // namespace kdpm
