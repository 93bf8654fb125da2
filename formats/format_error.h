#pragma once
// The one exception type of the file layer: its message is a complete, one-line reason.
#include <stdexcept>
#include <string>

namespace kdpm {

class FormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace kdpm
