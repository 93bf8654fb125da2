#include "tools/bench/host_description.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <thread>

#include "runtime/geometry/kd_packet_traversal.h"

namespace kdpm::bench {

std::string cpu_model_from_cpuinfo(const std::string& cpuinfo) {
    std::istringstream lines(cpuinfo);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        const auto begin = line.find_first_not_of(" \t", colon + 1);
        if (begin == std::string::npos) continue;
        const auto end = line.find_last_not_of(" \t\r");
        return line.substr(begin, end - begin + 1);
    }
    return "unknown CPU";
}

std::string host_description() {
    std::ifstream in("/proc/cpuinfo");
    std::stringstream text;
    text << in.rdbuf();
    std::string isa = "scalar";
#if defined(KDPM_PACKET_SIMD)
    isa = packet_detail::cpu_has_avx512() ? "AVX-512" : packet_detail::cpu_has_avx2() ? "AVX2" : "SSE2";
#endif
    return "host: " + cpu_model_from_cpuinfo(text.str()) + ", " +
           std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " hardware threads, kdpm's ray packets in " + isa;
}

}  // namespace kdpm::bench
