#pragma once
// cli::Args knows only --long options; kdpm-render also accepts the customary "-o FILE" by
// rewriting it to "--output FILE" before parsing.
#include <string>
#include <vector>

namespace kdpm {

class OutputShorthand {
public:
    OutputShorthand(int argc, char** argv) {
        for (int i = 0; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "-o")
                args_.push_back("--output");
            else if (a.size() > 2 && a.rfind("-o", 0) == 0)
                args_.push_back("--output=" + a.substr(2));
            else
                args_.push_back(a);
        }
        for (auto& s : args_) pointers_.push_back(s.data());
        pointers_.push_back(nullptr);
    }
    int argc() const { return static_cast<int>(args_.size()); }
    char** argv() { return pointers_.data(); }

private:
    std::vector<std::string> args_;
    std::vector<char*> pointers_;
};

}  // namespace kdpm
