#pragma once
// The benchmarks' tables: printed as Markdown (--markdown) or as aligned text, the first column
// left-aligned and the figures right-aligned; and printf-style formatting into a string.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace kdpm::bench {

inline std::string fmt(const char* f, ...) {
    char buf[512];
    va_list args;
    va_start(args, f);
    std::vsnprintf(buf, sizeof buf, f, args);
    va_end(args);
    return buf;
}

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    std::string render(bool markdown) const {
        std::vector<std::size_t> width(header.size(), 0);
        auto widen = [&](const std::vector<std::string>& r) {
            for (std::size_t i = 0; i < r.size() && i < width.size(); ++i) width[i] = std::max(width[i], r[i].size());
        };
        widen(header);
        for (const auto& r : rows) widen(r);
        std::string out;
        auto line = [&](const std::vector<std::string>& r) {
            out += markdown ? "|" : "";
            for (std::size_t i = 0; i < width.size(); ++i) {
                std::string cell = i < r.size() ? r[i] : "";
                if (markdown) {
                    out += " " + cell + " |";
                } else {
                    std::string pad(width[i] - cell.size(), ' ');
                    out += (i == 0 ? cell + pad : pad + cell) + "  ";
                }
            }
            out += "\n";
        };
        line(header);
        if (markdown) {
            out += "|";
            for (std::size_t i = 0; i < width.size(); ++i) out += i == 0 ? "---|" : "---:|";
            out += "\n";
        }
        for (const auto& r : rows) line(r);
        return out;
    }
};

}  // namespace kdpm::bench
