#include "driver/sid_values.hpp"

#include "driver/bindings.hpp"
#include "model/flexible.hpp"
#include "sid/reader.hpp"

#include <set>

namespace yamsc::driver {

namespace {

std::vector<Assignment> body_values(const model::Model& m, const std::string& body,
                                    const std::string& path) {
    int b = m.body_index(body);
    if (b < 0 || !m.bodies[static_cast<std::size_t>(b)].flex ||
        !m.bodies[static_cast<std::size_t>(b)].flex->symbolic)
        throw UserError("--sid: '" + body + "' is not a flexible body with `symbolic modes`");
    const model::Flexible& flex = *m.bodies[static_cast<std::size_t>(b)].flex;
    diag::Diagnostics diags;
    auto data = sid::read_sid_file(path, diags);
    if (!data || diags.has_errors())
        throw UserError("--sid: cannot use '" + path + "':\n" + diags.render());
    for (int k : flex.sid_modes)
        if (k >= data->nq)
            throw UserError("--sid: '" + path + "' has " + std::to_string(data->nq) +
                            " modes; the model uses mode " + std::to_string(k + 1));
    model::Flexible runtime = flex;
    runtime.sid = std::make_shared<const sid::Sid>(model::select_modes(*data, flex.sid_modes));
    std::set<std::string> declared;
    for (const auto& p : m.params) declared.insert(p.name);
    std::vector<Assignment> out;
    std::set<std::string> given;
    for (const auto& p : model::shape_parameters(body, runtime)) {
        if (!declared.count(p.name))
            throw UserError("--sid: entry " + p.name + " of '" + path +
                            "' is not zero, but was zero in the SID the model was compiled "
                            "with (recompile with this SID)");
        out.push_back({p.name, 0, p.value.value_or(0.0)});
        given.insert(p.name);
    }
    // Parameters of this body whose entry is zero in the new SID.
    for (const auto& name : model::shape_parameters(body, flex))
        if (!given.count(name.name)) out.push_back({name.name, 0, 0.0});
    return out;
}

} // namespace

std::vector<std::pair<std::string, std::string>> sid_spec_items(const std::string& spec) {
    std::vector<std::pair<std::string, std::string>> items;
    std::size_t start = 0;
    while (start < spec.size()) {
        std::size_t comma = spec.find(',', start);
        if (comma == std::string::npos) comma = spec.size();
        std::string item = spec.substr(start, comma - start);
        auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
            throw UsageError("--sid takes body=file.sid[,body=file.sid]");
        items.emplace_back(item.substr(0, eq), item.substr(eq + 1));
        start = comma + 1;
    }
    return items;
}

std::vector<Assignment> sid_parameter_values(const model::Model& m, const std::string& spec) {
    std::vector<Assignment> out;
    for (const auto& [body, path] : sid_spec_items(spec)) {
        auto values = body_values(m, body, path);
        out.insert(out.end(), values.begin(), values.end());
    }
    return out;
}

} // namespace yamsc::driver
