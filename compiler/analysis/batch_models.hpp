#pragma once
// The models of a `yamsc batch` run: each distinct model (and set of
// routines) loaded once, from the JIT cache when compiled before, and shared
// by every case that runs it.
#include "analysis/loaded_model.hpp"
#include "driver/commands.hpp"

#include <iosfwd>
#include <map>
#include <optional>
#include <string>

namespace yamsc::analysis {

class BatchModels {
public:
    /// Diagnostics and the compile notice go to `err` as they come.
    explicit BatchModels(std::ostream& err) : err_(err) {}

    /// The model a case with options `sim` runs, loaded unbound; nullptr when it
    /// has errors, with `error` saying so (the lines of its diagnostics that state
    /// an error), for every case that uses it.
    const Loaded* model_of(const driver::SimOptions& sim, std::string& error);

private:
    struct Entry {
        std::optional<Loaded> model;
        std::string error;
    };
    std::ostream& err_;
    std::map<std::string, Entry> models_; // by model path and routines
};

} // namespace yamsc::analysis
