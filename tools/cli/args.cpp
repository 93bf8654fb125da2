#include "tools/cli/args.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "tools/cli/version_text.h"

namespace kdpm::cli {

double parse_finite(const std::string& v) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw std::invalid_argument("'" + v + "' is not a finite number");
    return x;
}

namespace {

// CLI11 names a positional by its meta; it accepts only some characters there.
std::string positional_name(const std::string& meta) {
    std::string name = meta;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
    return name;
}

}  // namespace

Args::Args(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {}

Args& Args::flag(const std::string& name, bool* target, const std::string& help) {
    options_.push_back({name, "", help, group_, true, 0, [target](const std::vector<std::string>&) { *target = true; }});
    return *this;
}

Args& Args::option(const std::string& name, std::string* target, const std::string& meta, const std::string& help) {
    return option(name, meta, help, [target](const std::string& v) { *target = v; });
}

Args& Args::option(const std::string& name, int* target, const std::string& meta, const std::string& help,
                   long long min, long long max) {
    return option(name, meta, help, [=](const std::string& v) {
        errno = 0;
        char* end = nullptr;
        const long long x = std::strtoll(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || errno == ERANGE) throw std::invalid_argument("'" + v + "' is not an integer");
        if (x < min || x > max)
            throw std::invalid_argument(v + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]");
        *target = static_cast<int>(x);
    });
}

Args& Args::option(const std::string& name, double* target, const std::string& meta, const std::string& help,
                   double min, double max) {
    return option(name, meta, help, [=](const std::string& v) {
        const double x = parse_finite(v);
        if (x < min || x > max)
            throw std::invalid_argument(v + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]");
        *target = x;
    });
}

Args& Args::option(const std::string& name, const std::string& meta, const std::string& help,
                   std::function<void(const std::string&)> parse) {
    options_.push_back({name, meta, help, group_, false, 1,
                        [parse = std::move(parse)](const std::vector<std::string>& v) { parse(v.back()); }});
    return *this;
}

Args& Args::option(const std::string& name, std::optional<std::array<double, 3>>* target, const std::string& help) {
    options_.push_back({name, "X Y Z", help, group_, false, 3, [target](const std::vector<std::string>& v) {
                            if (v.size() < 3) throw std::invalid_argument("needs three numbers X Y Z");
                            std::array<double, 3> xyz{};
                            // The last three words: an option given twice takes its last value.
                            for (int i = 0; i < 3; ++i) xyz[i] = parse_finite(v[v.size() - 3 + i]);
                            *target = xyz;
                        }});
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
    short_names_.push_back({letter, long_name});
    return *this;
}

Args& Args::group(const std::string& title) {
    group_ = title;
    return *this;
}

void Args::describe(CLI::App& app) const {
    app.description(summary_);
    app.name(program_);
    app.get_formatter()->column_width(30);
    app.set_help_flag("-h,--help", "show this help and exit");
    app.set_version_flag("--version", [program = program_] { return version_text(program); },
                         "show the kdpm version, file format versions and backends, and exit");
    app.set_config("--config", "", "read options from FILE (TOML or INI: name = value, same names as the options)")
        ->type_name("FILE");
    for (const auto& p : positionals_) {
        if (p.many) {
            const CLI::callback_t collect = [many = p.many](const CLI::results_t& r) {
                many->insert(many->end(), r.begin(), r.end());
                return true;
            };
            app.add_option(positional_name(p.meta), collect, p.help)
                ->type_name("")
                ->expected(-1)  // one or more, also after options
                ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
            continue;
        }
        const CLI::callback_t store = [target = p.target](const CLI::results_t& r) {
            *target = r.back();
            return true;
        };
        app.add_option(positional_name(p.meta), store, p.help)
            ->type_name(p.required ? "" : "(optional)")
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    }
    for (const auto& o : options_) {
        std::string names = "--" + o.name;
        for (const auto& [letter, long_name] : short_names_)
            if (long_name == o.name) names = std::string("-") + letter + "," + names;
        const CLI::callback_t apply = [&o](const CLI::results_t& r) {
            try {
                o.apply(r);
            } catch (const std::invalid_argument& e) {
                throw CLI::ValidationError("--" + o.name, e.what());
            }
            return true;
        };
        CLI::Option* opt = o.is_flag ? app.add_flag_callback(names, [apply] { apply({}); }, o.help)
                                      : app.add_option(names, apply, o.help);
        opt->group(o.group);
        if (!o.is_flag) {
            opt->type_name(o.meta)->expected(o.values)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
            if (o.values > 1) opt->option_text(o.meta);  // not CLI11's "X Y Z x 3"
        }
    }
}

std::string Args::usage() const {
    CLI::App app;
    describe(app);
    return app.help();
}

void Args::fail(const std::string& why) const {
    std::cerr << program_ << ": error: " << why << " (see --help)\n";
    std::exit(2);
}

void Args::parse(int argc, char** argv) {
    CLI::App app;
    describe(app);
    app.allow_extras();
    try {
        app.parse(argc, argv);
        // Checked here rather than by CLI11, so that an unknown option is named as such first.
        for (const std::string& extra : app.remaining())
            if (extra != "--") fail(extra.rfind("-", 0) == 0 && extra != "-" ? "unknown option " + extra : "unexpected argument '" + extra + "'");
        for (const auto& p : positionals_)
            if (p.required && app.get_option(positional_name(p.meta))->count() == 0) fail("missing " + p.meta);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        std::exit(0);
    } catch (const CLI::CallForVersion& e) {
        std::cout << e.what();
        std::exit(0);
    } catch (const CLI::ParseError& e) {
        std::string why = e.what();
        for (char& c : why)
            if (c == '\n') c = ' ';
        fail(why);
    }
}

}  // namespace kdpm::cli
