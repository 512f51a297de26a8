#pragma once
// The export targets of `yamsc MODEL -o FILE` as a registry: one row per
// target, each defined in its own file (driver/target_<name>.cpp) and listed
// once in targets.cpp. The CLI chooses one by --lang or by the extension of -o;
// compile() asks the row what applies and calls its emitter.
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "driver/commands.hpp"
#include "driver/pipeline.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace yamsc::driver {

/// What an emitter is given: the options, the front end's model and System
/// and, for a target that prints the code module, the module.
struct TargetInput {
    const CompileOptions& options;
    const FrontEnd& front_end;
    const codegen::Module* module; // null unless Target::prints_module
    const codegen::EmitOptions& emit;
};

struct Target {
    Language language;
    const char* name;                    // --lang NAME
    std::vector<std::string> extensions; // of -o that choose it, without the dot
    bool nested_namespaces;              // --namespace a::b (else one identifier)
    bool header;                         // --header applies
    bool single_precision;               // --real float applies
    /// Prints codegen's Module (built after the passes); else reads the System.
    bool prints_module;
    codegen::EmittedFiles (*emit)(const TargetInput& in);
};

/// Every target, in the order of Language.
const std::vector<const Target*>& targets();
const Target& target(Language language);
/// The target an output file's extension ("cpp", no dot) chooses; null for none.
const Target* target_for_extension(std::string_view extension);
/// The target of --lang NAME; null for none.
const Target* target_named(std::string_view name);
/// "cpp|c|latex", for messages.
std::string target_names(const char* separator);

// The rows (driver/target_<name>.cpp).
extern const Target cpp_target;
extern const Target c_target;
extern const Target latex_target;

} // namespace yamsc::driver
