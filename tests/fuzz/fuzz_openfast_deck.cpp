// libFuzzer target: an OpenFAST input file (formats/openfast) through the entry
// scanner every deck file goes through, and the strain-gauge lists of an ElastoDyn
// main file. Properties: no crash, no sanitizer report, no exception; every entry
// has a key and lies on a line of the file (after the banner and the title) at a
// column of that line.
#include "openfast/deck.hpp"
#include "openfast/gauge_nodes.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    const diag::SourceFile file("fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    for (const openfast::DeckEntry& e : openfast::scan_deck_entries(file)) {
        if (e.key.empty() || e.line < 3 || e.line > file.line_count()) std::abort();
        if (e.col < 1 || static_cast<std::size_t>(e.col) > file.line(e.line).size() + 1)
            std::abort();
    }
    (void)openfast::read_gauge_nodes(file);
    return 0;
}
