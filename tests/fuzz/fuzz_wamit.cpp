// libFuzzer target: one text through WAMIT's three readers (.1, .3, .hst;
// wamit::read_radiation, read_excitation, read_hydrostatics).
// Properties: no crash, no sanitizer report, no exception; a rejected file reports
// an error; accepted rows have mode indices from 1 to max_mode, damping exactly on
// the rows of positive period, a positive period on every .3 row.
#include "wamit/wamit.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

bool mode(int i) {
    return i >= 1 && i <= yamsc::wamit::max_mode;
}

template <class Table> void check_rejection(const Table& t, const yamsc::diag::Diagnostics& d) {
    (void)d.render();
    if (!t && !d.has_errors()) std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.1", std::string(reinterpret_cast<const char*>(data), size));
    {
        diag::Diagnostics diags;
        const auto r = wamit::read_radiation(file, diags);
        check_rejection(r, diags);
        if (r)
            for (const auto& row : r->rows)
                if (!mode(row.i) || !mode(row.j) || (row.period > 0) != row.damping.has_value())
                    std::abort();
    }
    {
        diag::Diagnostics diags;
        const auto x = wamit::read_excitation(file, diags);
        check_rejection(x, diags);
        if (x)
            for (const auto& row : x->rows)
                if (!mode(row.i) || !(row.period > 0)) std::abort();
    }
    {
        diag::Diagnostics diags;
        const auto h = wamit::read_hydrostatics(file, diags);
        check_rejection(h, diags);
        if (h)
            for (const auto& row : h->rows)
                if (!mode(row.i) || !mode(row.j)) std::abort();
    }
    return 0;
}
