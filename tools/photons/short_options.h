#pragma once
// cli::Args knows only --long options; the photon tools also accept customary short ones
// ("-o FILE", "-n COUNT") by rewriting them to their long names before parsing.
#include <map>
#include <string>
#include <vector>

namespace kdpm::photon_tools {

class ShortOptions {
public:
    ShortOptions(int argc, char** argv, const std::map<std::string, std::string>& long_names) {
        for (int i = 0; i < argc; ++i) {
            std::string a = argv[i];
            auto it = i > 0 ? long_names.find(a) : long_names.end();
            storage_.push_back(it != long_names.end() ? "--" + it->second : a);
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
