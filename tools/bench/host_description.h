#pragma once
// The line kdpm-bench prints above its tables: which CPU measured them. The ratios to Embree
// move with the CPU (its SIMD width, cache sizes, memory latency), so a table means little
// without it: e.g. the Conference room's geometry build took 4.1-4.4x Embree's HQ build on the
// AVX-512 hosts of earlier runs and 6.2x on an AMD EPYC with AVX2 only.
#include <string>

namespace kdpm::bench {

// The first "model name" of a /proc/cpuinfo text, trimmed; "unknown CPU" where there is none.
std::string cpu_model_from_cpuinfo(const std::string& cpuinfo);

// "host: <model>, <n> hardware threads, kdpm's ray packets in <ISA>" for this machine (the
// packet walk is the one kernel that picks its instruction set at run time).
std::string host_description();

}  // namespace kdpm::bench
