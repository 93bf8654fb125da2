#include "tools/cli/args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace kdpm::cli {

Args::Args(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {}

Args& Args::flag(const std::string& name, bool* target, const std::string& help) {
    options_.push_back({name, "", help, true, [target](const std::string&) { *target = true; }});
    return *this;
}

Args& Args::option(const std::string& name, std::string* target, const std::string& meta, const std::string& help) {
    options_.push_back({name, meta, help, false, [target](const std::string& v) { *target = v; }});
    return *this;
}

Args& Args::option(const std::string& name, int* target, const std::string& meta, const std::string& help,
                   long long min, long long max) {
    options_.push_back({name, meta, help, false, [=](const std::string& v) {
                            errno = 0;
                            char* end = nullptr;
                            long long x = std::strtoll(v.c_str(), &end, 10);
                            if (v.empty() || *end != '\0' || errno == ERANGE)
                                throw std::invalid_argument("'" + v + "' is not an integer");
                            if (x < min || x > max)
                                throw std::invalid_argument(v + " is out of range [" + std::to_string(min) + ", " +
                                                            std::to_string(max) + "]");
                            *target = static_cast<int>(x);
                        }});
    return *this;
}

Args& Args::option(const std::string& name, double* target, const std::string& meta, const std::string& help,
                   double min, double max) {
    options_.push_back({name, meta, help, false, [=](const std::string& v) {
                            char* end = nullptr;
                            double x = std::strtod(v.c_str(), &end);
                            if (v.empty() || *end != '\0' || !std::isfinite(x))
                                throw std::invalid_argument("'" + v + "' is not a finite number");
                            if (x < min || x > max)
                                throw std::invalid_argument(v + " is out of range [" + std::to_string(min) + ", " +
                                                            std::to_string(max) + "]");
                            *target = x;
                        }});
    return *this;
}

Args& Args::option(const std::string& name, const std::string& meta, const std::string& help,
                   std::function<void(const std::string&)> parse) {
    options_.push_back({name, meta, help, false, std::move(parse)});
    return *this;
}

Args& Args::positional(const std::string& meta, std::string* target, const std::string& help, bool required) {
    positionals_.push_back({meta, help, target, required});
    return *this;
}

Args& Args::positionals(const std::string& meta, std::vector<std::string>* target, const std::string& help) {
    positionals_.push_back({meta + "...", help, nullptr, true, target});
    return *this;
}

Args& Args::short_name(char letter, const std::string& long_name) {
    short_names_.push_back({std::string("-") + letter, long_name});
    return *this;
}

std::string Args::usage() const {
    std::string u = "usage: " + program_ + " [options]";
    for (const auto& p : positionals_) u += p.required ? " " + p.meta : " [" + p.meta + "]";
    u += "\n" + summary_ + "\n";
    if (!positionals_.empty()) u += "\narguments:\n";
    for (const auto& p : positionals_) u += "  " + p.meta + std::string(std::max<int>(2, 24 - (int)p.meta.size()), ' ') + p.help + "\n";
    u += "\noptions:\n";
    for (const auto& o : options_) {
        std::string left = "--" + o.name + (o.meta.empty() ? "" : " " + o.meta);
        for (const auto& [short_form, long_name] : short_names_)
            if (long_name == o.name) left = short_form + ", " + left;
        u += "  " + left + std::string(std::max<int>(2, 24 - (int)left.size()), ' ') + o.help + "\n";
    }
    u += "  --help                  show this help\n";
    return u;
}

void Args::fail(const std::string& why) const {
    std::cerr << program_ << ": error: " << why << " (see --help)\n";
    std::exit(2);
}

void Args::parse(int argc, char** argv) {
    std::size_t next_positional = 0;
    bool only_positionals = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (!only_positionals)
            for (const auto& [short_form, long_name] : short_names_)
                if (a == short_form) a = "--" + long_name;
        if (!only_positionals && a == "--") {
            only_positionals = true;
            continue;
        }
        if (!only_positionals && (a == "--help" || a == "-h")) {
            std::cout << usage();
            std::exit(0);
        }
        if (!only_positionals && a.size() > 2 && a.rfind("--", 0) == 0) {
            std::string name = a.substr(2), value;
            bool has_value = false;
            if (auto eq = name.find('='); eq != std::string::npos) {
                value = name.substr(eq + 1);
                name = name.substr(0, eq);
                has_value = true;
            }
            const Option* opt = nullptr;
            for (const auto& o : options_)
                if (o.name == name) opt = &o;
            if (!opt) fail("unknown option --" + name);
            if (opt->is_flag) {
                if (has_value) fail("--" + name + " takes no value");
            } else if (!has_value) {
                if (i + 1 >= argc) fail("--" + name + " needs a value");
                value = argv[++i];
            }
            try {
                opt->apply(value);
            } catch (const std::invalid_argument& e) {
                fail("--" + name + ": " + e.what());
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-' && !only_positionals && a != "-") fail("unknown option " + a);
        if (next_positional >= positionals_.size()) fail("unexpected argument '" + a + "'");
        if (auto* many = positionals_[next_positional].many) {
            many->push_back(a);
            continue;
        }
        *positionals_[next_positional++].target = a;
    }
    for (std::size_t i = next_positional; i < positionals_.size(); ++i)
        if (positionals_[i].required && !(positionals_[i].many && !positionals_[i].many->empty()))
            fail("missing " + positionals_[i].meta);
}

}  // namespace kdpm::cli
