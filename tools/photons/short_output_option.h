#pragma once
// cli::Args knows only --long options; the photon tools also accept the customary "-o FILE"
// by rewriting it to "--output FILE" before parsing.
#include <string>
#include <vector>

namespace kdpm::photon_tools {

class ShortOutputOption {
public:
    ShortOutputOption(int argc, char** argv) {
        for (int i = 0; i < argc; ++i) {
            std::string a = argv[i];
            storage_.push_back(a == "-o" ? "--output" : a.rfind("-o", 0) == 0 && a.size() > 2 && a[2] != '-' ? "--output=" + a.substr(2) : a);
        }
        for (auto& s : storage_) pointers_.push_back(s.data());
        pointers_.push_back(nullptr);
    }
    int argc() const { return static_cast<int>(storage_.size()); }
    char** argv() { return pointers_.data(); }

private:
    std::vector<std::string> storage_;
    std::vector<char*> pointers_;
};

}  // namespace kdpm::photon_tools
