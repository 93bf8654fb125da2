#include "builders/geometry/sah/large_stack.h"

#include <pthread.h>

#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace kdpm {

namespace {

struct Job {
    const std::function<void()>* fn;
    std::exception_ptr error;
};

extern "C" void* run_job(void* arg) {
    auto* job = static_cast<Job*>(arg);
    try {
        (*job->fn)();
    } catch (...) {
        job->error = std::current_exception();
    }
    return nullptr;
}

}  // namespace

void run_with_large_stack(const std::function<void()>& fn, std::size_t stack_bytes) {
    Job job{&fn, nullptr};
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, stack_bytes);
    pthread_t thread;
    const int err = pthread_create(&thread, &attr, run_job, &job);
    pthread_attr_destroy(&attr);
    if (err != 0) {
        // No room for a large stack (a tight address-space limit): run here instead.
        fn();
        return;
    }
    pthread_join(thread, nullptr);
    if (job.error) std::rethrow_exception(job.error);
}

}  // namespace kdpm
