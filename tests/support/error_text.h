#pragma once
// The one-line reason an operation refuses its input with, for tests that check which fault a
// check names first.
#include <exception>
#include <string>

namespace kdpm::test {

// What `run` throws (its what()), or "accepted" when it returns normally.
template <class Run>
std::string error_text(Run&& run) {
    try {
        run();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace kdpm::test
