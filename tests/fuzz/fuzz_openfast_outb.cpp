// libFuzzer target: OpenFAST's binary output (formats/table/openfast_binary.cpp).
// Properties: no crash, no sanitizer report, no allocation beyond what the bytes
// hold; a rejected file throws diag::UserError only, naming a byte offset; an
// accepted one has one name per column, equal columns, time strictly rising and
// every value finite.
#include "diag/errors.hpp"
#include "table/openfast_binary.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    table::Table t;
    try {
        t = table::parse_openfast_binary(std::string(reinterpret_cast<const char*>(data), size),
                                         "f.outb");
    } catch (const diag::UserError& e) {
        if (std::string(e.what()).rfind("f.outb: byte ", 0) != 0) std::abort();
        return 0;
    }
    if (t.columns.size() < 2 || t.data.size() != t.columns.size()) std::abort();
    const std::size_t rows = t.data[0].size();
    if (rows == 0) std::abort();
    for (const auto& c : t.data) {
        if (c.size() != rows) std::abort();
        for (double v : c)
            if (!std::isfinite(v)) std::abort();
    }
    for (std::size_t i = 1; i < rows; ++i)
        if (!(t.data[0][i] > t.data[0][i - 1])) std::abort();
    return 0;
}
