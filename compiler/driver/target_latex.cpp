// --lang latex: the equations (exact and approximated) and the linear model,
// printed from the System (codegen/emit_latex.hpp).
#include "codegen/emit_latex.hpp"
#include "codegen/latex_printer.hpp"
#include "driver/targets.hpp"

namespace yamsc::driver {

namespace {

codegen::EmittedFiles emit(const TargetInput& in) {
    codegen::LatexInput latex;
    latex.system = &*in.front_end.system;
    for (const model::Approximation& a : in.front_end.model->approximations) {
        std::string names;
        for (const auto& s : a.symbols)
            names += (names.empty() ? "$" : ", $") + codegen::latex::symbol_name(s.name) + "$";
        latex.approximations.push_back(names + " to order " + std::to_string(a.order));
    }
    // The document depends on the equations only: no other option is recorded.
    codegen::EmitOptions options = in.emit;
    options.command_line = "--lang latex";
    return {codegen::emit_latex(latex, options), ""};
}

} // namespace

const Target latex_target{Language::latex,
                          "latex",
                          {"tex"},
                          /*nested_namespaces=*/true,
                          /*header=*/false,
                          /*single_precision=*/false,
                          /*prints_module=*/false,
                          emit};

} // namespace yamsc::driver
