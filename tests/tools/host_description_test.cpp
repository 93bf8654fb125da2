// kdpm-bench names the CPU its ratios were measured on: the model from /proc/cpuinfo's text.
#include <catch2/catch.hpp>

#include <string>

#include "tools/bench/host_description.h"

using namespace kdpm::bench;

TEST_CASE("kdpm-bench reads the CPU model from /proc/cpuinfo's first model name", "[tools][bench]") {
    const std::string two_cores =
        "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC 7B13 64-Core Processor  \n"
        "flags\t\t: fpu avx2\n\nprocessor\t: 1\nmodel name\t: Other\n";
    CHECK(cpu_model_from_cpuinfo(two_cores) == "AMD EPYC 7B13 64-Core Processor");
    CHECK(cpu_model_from_cpuinfo("model name\t: Intel(R) Xeon(R) Platinum 8375C CPU @ 2.90GHz\r\n") ==
          "Intel(R) Xeon(R) Platinum 8375C CPU @ 2.90GHz");
}

TEST_CASE("kdpm-bench says so when /proc/cpuinfo names no model", "[tools][bench]") {
    CHECK(cpu_model_from_cpuinfo("") == "unknown CPU");
    CHECK(cpu_model_from_cpuinfo("processor\t: 0\nCPU implementer\t: 0x41\n") == "unknown CPU");
    CHECK(cpu_model_from_cpuinfo("model name\t:   \n") == "unknown CPU");
    CHECK(host_description().rfind("host: ", 0) == 0);
}
