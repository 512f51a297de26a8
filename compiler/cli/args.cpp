#include "cli/args.hpp"

#include <cctype>

namespace yamsc::cli {

namespace {

/// An option's name, not a value ("-1", "-.5" and "-" are values).
bool is_option(const std::string& a) {
    return a.size() > 1 && a[0] == '-' && !(std::isdigit(a[1]) || a[1] == '.');
}

} // namespace

Args::Args(int argc, char** argv, int first, const OptionNames& names) {
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (is_option(a)) {
            std::string name = a, value;
            bool has_value = false;
            if (auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
                name = a.substr(0, eq);
                value = a.substr(eq + 1);
                has_value = true;
            }
            if (names.flags.count(name)) {
                if (has_value) throw UsageError(name + " takes no value");
                values_[name] = "1";
            } else if (names.valued.count(name)) {
                if (!has_value) {
                    if (i + 1 >= argc) throw UsageError(name + " needs a value");
                    value = argv[++i];
                    if (names.lists.count(name))
                        while (i + 1 < argc && !is_option(argv[i + 1]))
                            value += std::string(",") + argv[++i];
                }
                if (values_.count(name)) throw UsageError(name + " is given twice");
                values_[name] = value;
            } else {
                throw UsageError("unknown option '" + name + "'");
            }
        } else {
            positional_.push_back(a);
        }
    }
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

std::string Args::model() const {
    if (positional_.size() != 1)
        throw UsageError(positional_.empty() ? "no model file given"
                                             : "one model file expected, got " +
                                                   std::to_string(positional_.size()));
    return positional_[0];
}

std::vector<driver::Assignment> Args::assignments(const std::string& name) const {
    return has(name) ? driver::parse_assignments(get(name), name)
                     : std::vector<driver::Assignment>{};
}

double Args::number(const std::string& name, double fallback) const {
    return has(name) ? driver::parse_value(get(name), name) : fallback;
}

std::vector<std::string> comma_list(const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0; !text.empty() && start <= text.size();) {
        std::size_t comma = text.find(',', start);
        if (comma == std::string::npos) comma = text.size();
        items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

} // namespace yamsc::cli
