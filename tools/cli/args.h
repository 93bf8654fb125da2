#pragma once
// A small command-line parser shared by the kdpm tools: --name VALUE / --name=VALUE options,
// flags, positionals, numeric range checks, and --help. Errors end the program with a one-line
// message and exit code 2.
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace kdpm::cli {

class Args {
public:
    Args(std::string program, std::string summary);

    Args& flag(const std::string& name, bool* target, const std::string& help);
    Args& option(const std::string& name, std::string* target, const std::string& meta, const std::string& help);
    Args& option(const std::string& name, int* target, const std::string& meta, const std::string& help,
                 long long min = std::numeric_limits<int>::min(), long long max = std::numeric_limits<int>::max());
    Args& option(const std::string& name, double* target, const std::string& meta, const std::string& help,
                 double min = -std::numeric_limits<double>::infinity(),
                 double max = std::numeric_limits<double>::infinity());
    Args& positional(const std::string& meta, std::string* target, const std::string& help, bool required = true);
    // The remaining arguments, one or more (last positional only).
    Args& positionals(const std::string& meta, std::vector<std::string>* target, const std::string& help);
    // Options whose value needs more than a range check (e.g. an enum); `check` throws
    // std::invalid_argument with the reason.
    Args& option(const std::string& name, const std::string& meta, const std::string& help,
                 std::function<void(const std::string&)> parse);

    // A customary one-letter spelling of a long option ("-o FILE" for "--output FILE").
    Args& short_name(char letter, const std::string& long_name);

    void parse(int argc, char** argv);  // exits on --help (0) or error (2)
    const std::string& program() const { return program_; }
    std::string usage() const;

private:
    struct Option {
        std::string name, meta, help;
        bool is_flag = false;
        std::function<void(const std::string&)> apply;
    };
    struct Positional {
        std::string meta, help;
        std::string* target;
        bool required;
        std::vector<std::string>* many = nullptr;
    };
    [[noreturn]] void fail(const std::string& why) const;

    std::string program_, summary_;
    std::vector<Option> options_;
    std::vector<Positional> positionals_;
    std::vector<std::pair<std::string, std::string>> short_names_;  // "-o" -> "output"
};

}  // namespace kdpm::cli
