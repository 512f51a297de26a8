#pragma once
// The arguments of one command: `--name value`, `--name=value`, flags and
// positionals, checked against the options the command declares.
#include "diag/errors.hpp"
#include "driver/values.hpp"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::cli {

using diag::UsageError;

/// The options a command takes: those with a value and the flags. A valued
/// option also in `lists` takes every argument after it up to the next option
/// (`--reference of/*.outb`, as the shell expands it), joined by commas.
struct OptionNames {
    std::set<std::string> valued;
    std::set<std::string> flags;
    std::set<std::string> lists{};
};

class Args {
public:
    /// argv[first..argc): any option not in `names` is a usage error.
    Args(int argc, char** argv, int first, const OptionNames& names);

    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string get(const std::string& name, const std::string& fallback = "") const;
    /// The one positional argument (the model, table or manifest).
    std::string model() const;
    const std::vector<std::string>& positionals() const { return positional_; }
    std::vector<driver::Assignment> assignments(const std::string& name) const;
    double number(const std::string& name, double fallback) const;

private:
    std::map<std::string, std::string> values_;
    std::vector<std::string> positional_;
};

/// The value of option `name` among `choices` (its fallback when not given);
/// anything else is a usage error that lists the choices.
template <class Enum>
Enum choice(const Args& a, const std::string& name, Enum fallback,
            const std::vector<std::pair<std::string, Enum>>& choices) {
    if (!a.has(name)) return fallback;
    const std::string given = a.get(name);
    std::string names;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (choices[i].first == given) return choices[i].second;
        names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].first;
    }
    throw UsageError(name + " must be " + names + ", not '" + given + "'");
}

/// "a,b,c" -> {"a", "b", "c"}; "" -> {}.
std::vector<std::string> comma_list(const std::string& text);

} // namespace yamsc::cli
