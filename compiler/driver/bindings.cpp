#include "driver/bindings.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>

namespace yamsc::driver {

namespace {

int index_of(const std::vector<std::string>& names, const std::string& name) {
    auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

} // namespace

std::vector<double> bind_named(const std::vector<std::string>& names,
                               const std::vector<std::optional<double>>& defaults,
                               const std::vector<Assignment>& assignments,
                               const std::string& what) {
    std::vector<std::optional<double>> values = defaults;
    for (const auto& a : assignments) {
        int i = index_of(names, a.name);
        if (i < 0 || a.primes != 0)
            throw UserError("unknown " + what + " '" + a.name + std::string(a.primes, '\'') + "'" +
                            diag::did_you_mean(a.name, names));
        values[static_cast<std::size_t>(i)] = a.value;
    }
    std::vector<double> out;
    std::string missing;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (!values[i]) missing += (missing.empty() ? "" : ", ") + names[i];
        out.push_back(values[i].value_or(0.0));
    }
    if (!missing.empty())
        throw UserError(what + " without a value: " + missing + " (give it with --set " +
                        names[static_cast<std::size_t>(
                            std::find_if(values.begin(), values.end(), [](auto& v) { return !v; }) -
                            values.begin())] +
                        "=...)");
    return out;
}

void bind_state(const std::vector<std::string>& dofs, const std::vector<Assignment>& assignments,
                std::vector<double>& q, std::vector<double>& qd, const std::string& option) {
    q.assign(dofs.size(), 0.0);
    qd.assign(dofs.size(), 0.0);
    for (const auto& a : assignments) {
        int i = index_of(dofs, a.name);
        if (i < 0 || a.primes > 1)
            throw UserError(option + ": unknown DOF '" + a.name + std::string(a.primes, '\'') +
                            "'" + diag::did_you_mean(a.name, dofs));
        (a.primes == 0 ? q : qd)[static_cast<std::size_t>(i)] = a.value;
    }
}

std::vector<double> sized(const std::vector<double>& v, std::size_t n, const std::string& option) {
    if (v.size() != n)
        throw UsageError(option + " takes " + std::to_string(n) + " values, got " +
                         std::to_string(v.size()));
    return v;
}

} // namespace yamsc::driver
