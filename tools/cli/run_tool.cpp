#include "tools/cli/run_tool.h"

#include <exception>
#include <iostream>
#include <new>

namespace kdpm::cli {

int run_tool(const char* program, const std::function<int()>& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        std::cerr << program << ": error: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << "\n";
    } catch (...) {
        std::cerr << program << ": error: unknown failure\n";
    }
    return 1;
}

}  // namespace kdpm::cli
