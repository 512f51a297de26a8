#include "analysis/fmu_description.hpp"

#include "text/number.hpp"
#include "text/xml.hpp"

#include <map>
#include <set>
#include <stdexcept>

namespace yamsc::analysis {

namespace {

using fmi::Causality;
using fmi::Initial;
using fmi::ValueType;
using fmi::Variability;
using fmi::Variable;

std::string attribute(const std::string& name, const std::string& value) {
    return " " + name + "=\"" + text::xml_escaped(value) + "\"";
}

const char* causality_name(Causality c) {
    switch (c) {
    case Causality::independent:
        return "independent";
    case Causality::parameter:
        return "parameter";
    case Causality::input:
        return "input";
    case Causality::output:
        return "output";
    case Causality::local:
        return "local";
    }
    throw std::logic_error("unknown causality");
}

const char* variability_name(Variability v) {
    switch (v) {
    case Variability::constant:
        return "constant";
    case Variability::fixed:
        return "fixed";
    case Variability::tunable:
        return "tunable";
    case Variability::discrete:
        return "discrete";
    case Variability::continuous:
        return "continuous";
    }
    throw std::logic_error("unknown variability");
}

const char* initial_name(Initial i) {
    switch (i) {
    case Initial::exact:
        return "exact";
    case Initial::approx:
        return "approx";
    case Initial::calculated:
        return "calculated";
    case Initial::none:
        break;
    }
    return nullptr;
}

bool has_start(const Variable& v) {
    return v.initial == Initial::exact || v.initial == Initial::approx ||
           v.causality == Causality::input;
}

std::string start_text(const Variable& v) {
    return v.type == ValueType::int32 ? std::to_string(static_cast<long long>(v.start))
                                      : text::shortest(v.start);
}

/// Units per value reference: from the description, else, for a derivative,
/// its variable's unit per second.
std::vector<std::string> units_of(const std::vector<Variable>& vars) {
    std::vector<std::string> units(vars.size());
    for (std::size_t k = 0; k < vars.size(); ++k) {
        units[k] = unit_in(vars[k].description);
        if (!units[k].empty() || !vars[k].derivative_of) continue;
        const std::string& of = units[*vars[k].derivative_of];
        if (of.empty()) continue;
        // rad -> rad/s -> rad/s2: the derivative's derivative gets one power more.
        if (of.size() > 2 && of.compare(of.size() - 2, 2, "/s") == 0)
            units[k] = of + "2";
        else
            units[k] = of + "/s";
    }
    return units;
}

std::string joined(const std::vector<std::uint32_t>& items) {
    std::string s;
    for (std::uint32_t i : items) s += (s.empty() ? "" : " ") + std::to_string(i);
    return s;
}

/// The model structure's lists, by value reference.
struct Structure {
    std::vector<std::uint32_t> outputs, derivatives, initial_unknowns;
    std::vector<std::uint32_t> states_and_inputs, initial_knowns;
};

Structure structure_of(const std::vector<Variable>& vars) {
    Structure s;
    std::set<std::uint32_t> states;
    for (const Variable& v : vars)
        if (v.derivative_of) states.insert(*v.derivative_of);
    for (const Variable& v : vars) {
        const std::uint32_t vr = v.value_reference;
        if (v.causality == Causality::output) s.outputs.push_back(vr);
        if (v.derivative_of) s.derivatives.push_back(vr);
        if ((v.causality == Causality::output || v.derivative_of) &&
            (v.initial == Initial::calculated || v.initial == Initial::approx))
            s.initial_unknowns.push_back(vr);
        const bool state = states.count(vr) > 0;
        if (state || v.causality == Causality::input) s.states_and_inputs.push_back(vr);
        // The knowns of initialization the model's values depend on: its inputs,
        // states and parameters (the co-simulation settings are not the model's).
        if (state || v.causality == Causality::input ||
            (v.causality == Causality::parameter && v.type == ValueType::float64 &&
             v.role == fmi::Role::parameter))
            s.initial_knowns.push_back(vr);
    }
    return s;
}

/// What a derivative depends on: q' (the derivative of q) is a state itself;
/// the others are the model's right-hand side.
std::vector<std::uint32_t> derivative_dependencies(const Variable& v, const Structure& s,
                                                   const std::set<std::uint32_t>& states) {
    if (states.count(v.value_reference)) return {v.value_reference};
    return s.states_and_inputs;
}

std::set<std::uint32_t> state_set(const std::vector<Variable>& vars) {
    std::set<std::uint32_t> states;
    for (const Variable& v : vars)
        if (v.derivative_of) states.insert(*v.derivative_of);
    return states;
}

void check_table(const std::vector<Variable>& vars) {
    for (std::size_t k = 0; k < vars.size(); ++k)
        if (vars[k].value_reference != k)
            throw std::logic_error("the variable table's value references are not its positions");
}

/// UnitDefinitions and DefaultExperiment, alike in both versions.
std::string units_and_experiment(const std::vector<std::string>& units, double step) {
    std::string out;
    const std::set<std::string> unit_names(units.begin(), units.end());
    if (unit_names.size() > (unit_names.count("") ? 1U : 0U)) {
        out += "  <UnitDefinitions>\n";
        for (const std::string& u : unit_names)
            if (!u.empty()) out += "    <Unit" + attribute("name", u) + "/>\n";
        out += "  </UnitDefinitions>\n";
    }
    return out + "  <DefaultExperiment" + attribute("startTime", "0") +
           (step > 0 ? attribute("stepSize", text::shortest(step)) : "") + "/>\n";
}

std::string fmi3(const DescriptionFacts& f, const std::vector<std::string>& units) {
    const std::vector<Variable>& vars = f.variables;
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription" +
                      attribute("fmiVersion", "3.0") + attribute("modelName", f.model_name) +
                      attribute("instantiationToken", f.token) +
                      attribute("description", f.description) +
                      attribute("generationTool", f.generation_tool) +
                      attribute("variableNamingConvention", "flat") + ">\n";
    out += "  <ModelExchange" + attribute("modelIdentifier", f.model_name) +
           attribute("needsCompletedIntegratorStep", f.block_states ? "true" : "false") +
           attribute("canGetAndSetFMUState", f.block_states ? "false" : "true") +
           attribute("providesDirectionalDerivatives", "true") + "/>\n";
    out += "  <CoSimulation" + attribute("modelIdentifier", f.model_name) +
           attribute("canHandleVariableCommunicationStepSize", "true") +
           attribute("canGetAndSetFMUState", f.block_states ? "false" : "true") +
           attribute("providesDirectionalDerivatives", "true") +
           (f.step > 0 ? attribute("fixedInternalStepSize", text::shortest(f.step)) : "") + "/>\n";
    out += units_and_experiment(units, f.step);
    out += "  <ModelVariables>\n";
    for (const Variable& v : vars) {
        const char* element = v.type == ValueType::int32 ? "Int32" : "Float64";
        out += std::string("    <") + element + attribute("name", v.name) +
               attribute("valueReference", std::to_string(v.value_reference));
        const std::string description = without_unit(v.description);
        if (!description.empty()) out += attribute("description", description);
        out += attribute("causality", causality_name(v.causality)) +
               attribute("variability", variability_name(v.variability));
        if (const char* initial = initial_name(v.initial)) out += attribute("initial", initial);
        if (v.type == ValueType::float64 && !units[v.value_reference].empty())
            out += attribute("unit", units[v.value_reference]);
        if (v.derivative_of) out += attribute("derivative", std::to_string(*v.derivative_of));
        if (has_start(v)) out += attribute("start", start_text(v));
        out += "/>\n";
    }
    out += "  </ModelVariables>\n  <ModelStructure>\n";
    const Structure s = structure_of(vars);
    const std::set<std::uint32_t> states = state_set(vars);
    for (std::uint32_t vr : s.outputs)
        out += "    <Output" + attribute("valueReference", std::to_string(vr)) +
               attribute("dependencies", joined(s.states_and_inputs)) + "/>\n";
    for (std::uint32_t vr : s.derivatives)
        out += "    <ContinuousStateDerivative" + attribute("valueReference", std::to_string(vr)) +
               attribute("dependencies", joined(derivative_dependencies(vars[vr], s, states))) +
               "/>\n";
    for (std::uint32_t vr : s.initial_unknowns)
        out += "    <InitialUnknown" + attribute("valueReference", std::to_string(vr)) +
               attribute("dependencies", joined(s.initial_knowns)) + "/>\n";
    out += "  </ModelStructure>\n</fmiModelDescription>\n";
    return out;
}

/// FMI 2.0 names variables by their 1-based position in ModelVariables.
std::vector<std::uint32_t> indices(const std::vector<std::uint32_t>& vrs) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t vr : vrs) out.push_back(vr + 1);
    return out;
}

std::string fmi2(const DescriptionFacts& f, const std::vector<std::string>& units) {
    const std::vector<Variable>& vars = f.variables;
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription" +
                      attribute("fmiVersion", "2.0") + attribute("modelName", f.model_name) +
                      attribute("guid", f.token) + attribute("description", f.description) +
                      attribute("generationTool", f.generation_tool) +
                      attribute("variableNamingConvention", "flat") +
                      attribute("numberOfEventIndicators", "0") + ">\n";
    out += "  <ModelExchange" + attribute("modelIdentifier", f.model_name) +
           attribute("completedIntegratorStepNotNeeded", f.block_states ? "false" : "true") +
           attribute("canGetAndSetFMUstate", f.block_states ? "false" : "true") +
           attribute("providesDirectionalDerivative", "true") + "/>\n";
    out += "  <CoSimulation" + attribute("modelIdentifier", f.model_name) +
           attribute("canHandleVariableCommunicationStepSize", "true") +
           attribute("canGetAndSetFMUstate", f.block_states ? "false" : "true") +
           attribute("providesDirectionalDerivative", "true") + "/>\n";
    out += units_and_experiment(units, f.step);
    out += "  <ModelVariables>\n";
    for (const Variable& v : vars) {
        out += "    <!-- index " + std::to_string(v.value_reference + 1) + " -->\n";
        out += "    <ScalarVariable" + attribute("name", v.name) +
               attribute("valueReference", std::to_string(v.value_reference));
        const std::string description = without_unit(v.description);
        if (!description.empty()) out += attribute("description", description);
        out += attribute("causality", causality_name(v.causality)) +
               attribute("variability", variability_name(v.variability));
        if (const char* initial = initial_name(v.initial)) out += attribute("initial", initial);
        out += ">\n      <";
        out += v.type == ValueType::int32 ? "Integer" : "Real";
        if (v.type == ValueType::float64 && !units[v.value_reference].empty())
            out += attribute("unit", units[v.value_reference]);
        if (v.derivative_of) out += attribute("derivative", std::to_string(*v.derivative_of + 1));
        if (has_start(v)) out += attribute("start", start_text(v));
        out += "/>\n    </ScalarVariable>\n";
    }
    out += "  </ModelVariables>\n  <ModelStructure>\n";
    const Structure s = structure_of(vars);
    const std::set<std::uint32_t> states = state_set(vars);
    auto unknowns = [&](const char* element, const std::vector<std::uint32_t>& vrs,
                        const std::function<std::vector<std::uint32_t>(std::uint32_t)>& deps) {
        if (vrs.empty()) return;
        out += std::string("    <") + element + ">\n";
        for (std::uint32_t vr : vrs)
            out += "      <Unknown" + attribute("index", std::to_string(vr + 1)) +
                   attribute("dependencies", joined(indices(deps(vr)))) + "/>\n";
        out += std::string("    </") + element + ">\n";
    };
    unknowns("Outputs", s.outputs, [&](std::uint32_t) { return s.states_and_inputs; });
    unknowns("Derivatives", s.derivatives,
             [&](std::uint32_t vr) { return derivative_dependencies(vars[vr], s, states); });
    unknowns("InitialUnknowns", s.initial_unknowns,
             [&](std::uint32_t) { return s.initial_knowns; });
    out += "  </ModelStructure>\n</fmiModelDescription>\n";
    return out;
}

} // namespace

std::string unit_in(const std::string& description) {
    const auto close = description.find_last_not_of(" \t");
    if (close == std::string::npos || description[close] != ']') return "";
    const auto open = description.rfind('[', close);
    if (open == std::string::npos) return "";
    std::string unit = description.substr(open + 1, close - open - 1);
    const auto first = unit.find_first_not_of(' '), last = unit.find_last_not_of(' ');
    return first == std::string::npos ? "" : unit.substr(first, last - first + 1);
}

std::string without_unit(const std::string& description) {
    if (unit_in(description).empty()) return description;
    std::string text = description.substr(0, description.rfind('['));
    const auto last = text.find_last_not_of(" \t");
    return last == std::string::npos ? "" : text.substr(0, last + 1);
}

std::string model_description(const DescriptionFacts& f) {
    check_table(f.variables);
    const std::vector<std::string> units = units_of(f.variables);
    return f.version == driver::FmiVersion::fmi3 ? fmi3(f, units) : fmi2(f, units);
}

} // namespace yamsc::analysis
