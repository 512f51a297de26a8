// libFuzzer target: command-line values (`--set a=1,b'=5deg`, `--q 1,2,3`) and
// lone expressions in the model language. Properties: no crash, no sanitizer
// report; bad values are a UsageError (exit 2), never another exception, and
// accepted values are finite.
#include "diag/diagnostics.hpp"
#include "driver/values.hpp"
#include "parse/parser.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        for (double v : driver::parse_list(text, "--q"))
            if (!std::isfinite(v)) std::abort();
    } catch (const driver::UsageError&) {
    }
    try {
        for (const auto& a : driver::parse_assignments(text, "--set"))
            if (a.name.empty() || !std::isfinite(a.value)) std::abort();
    } catch (const driver::UsageError&) {
    }
    diag::Diagnostics diags;
    auto expr =
        parse::parse_expression(std::make_shared<const diag::SourceFile>("--set", text), diags);
    if (!expr && !diags.has_errors()) std::abort();
    (void)diags.render();
    return 0;
}
