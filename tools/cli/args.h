#pragma once
// The command line of every kdpm tool, parsed by CLI11: --name VALUE / --name=VALUE options with
// range checks, flags, positionals, one-letter aliases, option groups in --help, --version, and
// --config FILE (TOML or INI: `name = value` per line, the same names as the options). An option
// given twice takes its last value, so scripts can append overrides. Errors end the program with
// a one-line message and exit code 2.
#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kdpm::cli {

// The whole text as a finite number, as the options read them; throws std::invalid_argument.
double parse_finite(const std::string& text);

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
    // Options whose value needs more than a range check (e.g. an enum); `parse` throws
    // std::invalid_argument with the reason.
    Args& option(const std::string& name, const std::string& meta, const std::string& help,
                 std::function<void(const std::string&)> parse);
    // An option followed by three finite numbers ("--eye X Y Z").
    Args& option(const std::string& name, std::optional<std::array<double, 3>>* target, const std::string& help);

    // A customary one-letter spelling of a long option ("-o FILE" for "--output FILE").
    Args& short_name(char letter, const std::string& long_name);
    // Options declared after this call are listed under `title` in --help.
    Args& group(const std::string& title);

    void parse(int argc, char** argv);  // exits on --help or --version (0) or error (2)
    const std::string& program() const { return program_; }
    std::string usage() const;

private:
    struct Option {
        std::string name, meta, help, group;
        bool is_flag = false;
        int values = 1;  // command-line words after the name
        std::function<void(const std::vector<std::string>&)> apply;
    };
    struct Positional {
        std::string meta, help;
        std::string* target;
        bool required;
        std::vector<std::string>* many = nullptr;
    };
    [[noreturn]] void fail(const std::string& why) const;
    void describe(CLI::App& app) const;

    std::string program_, summary_, group_ = "Options";
    std::vector<Option> options_;
    std::vector<Positional> positionals_;
    std::vector<std::pair<char, std::string>> short_names_;  // 'o' -> "output"
};

}  // namespace kdpm::cli
