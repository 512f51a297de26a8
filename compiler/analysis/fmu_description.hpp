#pragma once
// A unit's modelDescription.xml (FMI 3.0 or FMI 2.0) written from THE
// value-reference table the unit dispatches by (yamsc/fmi/variables.hpp), so
// the description and the binary cannot disagree: the variables with their
// causality, variability, initial and start, the units the model's comments
// give ("[m/s]" at the end of a description), model exchange and
// co-simulation, and the model structure (outputs, state derivatives, initial
// unknowns with their dependencies).
#include "driver/commands.hpp"

#include <yamsc/fmi/variables.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

struct DescriptionFacts {
    driver::FmiVersion version = driver::FmiVersion::fmi3;
    std::string model_name;      // also the model identifier
    std::string description;     // the model's title
    std::string token;           // instantiationToken (3.0), guid (2.0)
    std::string generation_tool; // "yamsc 0.1.0"
    double step = 0;             // the co-simulation fixed step [s]; 0: not declared
    std::vector<fmi::Variable> variables;
    /// Load blocks with discrete states (the unit cannot get and set its state;
    /// model exchange advances them at CompletedIntegratorStep).
    bool block_states = false;
};

/// The unit of a description that ends with one in brackets ("tip height [m]"
/// -> "m"), else "".
std::string unit_in(const std::string& description);

/// The description without its unit ("tip height [m]" -> "tip height").
std::string without_unit(const std::string& description);

/// The file's text.
std::string model_description(const DescriptionFacts& facts);

} // namespace yamsc::analysis
