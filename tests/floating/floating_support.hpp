#pragma once
// Shared by the floating tests: an OpenFAST deck converted by `from-openfast`, and
// the files it names for the platform's load blocks.
#include "analysis/load_blocks.hpp"
#include "diag/diagnostics.hpp"
#include "driver/commands.hpp"
#include "openfast/deck.hpp"
#include "openfast/from_openfast.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace floating {

inline const std::string data_dir = YAMSC_TEST_DATA_DIR;
inline const std::string work_dir = std::string(YAMSC_TEST_BINARY_DIR) + "/floating";

/// A whole file; one that cannot be opened fails the test.
inline std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The deck as `from-openfast` reads it (its files resolved, its DT).
inline yamsc::openfast::OpenFastDeck read_deck(const std::string& fst) {
    yamsc::diag::Diagnostics diags;
    auto deck = yamsc::openfast::read_openfast_deck(fst, diags);
    REQUIRE_MESSAGE(deck, diags.render());
    return *deck;
}

/// The deck's HydroDyn, SeaState and MAP++ files as the blocks' options (what the
/// converted model's header names for `yamsc sim`).
inline yamsc::analysis::BlockOptions deck_blocks(const yamsc::openfast::OpenFastDeck& d) {
    yamsc::analysis::BlockOptions b;
    b.hydro = d.offshore.hydro_file;
    b.sea_state = d.offshore.sea_state_file;
    b.mooring = d.offshore.mooring_file;
    return b;
}

/// `yamsc from-openfast fst -o work_dir/name.mbd`, in process: the model's path.
inline std::string convert(const std::string& fst, const std::string& name) {
    std::filesystem::create_directories(work_dir);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = fst;
    o.output = work_dir + "/" + name + ".mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    return o.output;
}

} // namespace floating
