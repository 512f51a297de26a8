// libFuzzer target: a model file through the parser and the checker, the path
// every `yamsc` command takes before deriving equations. The file pretends to
// live in models/, so `sid = "..."` and `beam "data/..."` reach the real data
// files of the seed models (and every reader behind them).
// Properties: no crash, no sanitizer report, no exception; every error is
// reported with a file, and a rejected model reports at least one error.
#include "data/file_source.hpp"
#include "diag/diagnostics.hpp"
#include "parse/parser.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto source = std::make_shared<const diag::SourceFile>(
        YAMSC_SOURCE_DIR "/models/fuzz_input.mbd",
        std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    auto ast = parse::parse_model(source, diags);
    if (!ast) {
        if (!diags.has_errors()) std::abort(); // rejected without saying why
    } else if (!diags.has_errors()) {
        auto model = data::check_model(*ast, diags);
        if (!model && !diags.has_errors()) std::abort();
    }
    for (const auto& d : diags.all())
        if (d.severity == diag::Severity::error && d.kind != diag::Kind::Io && !d.loc.file)
            std::abort(); // an error about the model must point into a file
    (void)diags.render();
    return 0;
}
