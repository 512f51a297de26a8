#pragma once
// The NREL 5-MW model from-openfast writes, with the AeroDyn file edited, for the
// tests of the blade-element block's unsteady aerodynamics and dynamic inflow
// (test_block_unsteady_*.cpp), and the columns of OpenFAST's reference runs and yamsc's.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "openfast/from_openfast.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace block_unsteady {

inline const std::string data_dir = YAMSC_TEST_DATA_DIR;

/// The deck's model with its blade-element block, DOFs as `dofs` says.
inline yamsc::runtime::ModelView model(const std::string& deck,
                                       std::vector<std::pair<std::string, bool>> dofs = {}) {
    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck + "/NREL-5MW.fst";
    o.output = deck + "/model.mbd";
    o.dofs = std::move(dofs);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    auto l =
        yamsc::analysis::load(o.output, {}, "", false, err, {}, yamsc::codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    yamsc::analysis::BlockOptions blocks;
    blocks.aero = deck + "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
    return yamsc::analysis::with_load_blocks(*l, blocks);
}

/// A CSV's columns by name (without the unit).
inline std::map<std::string, std::vector<double>> read_columns(const std::string& path) {
    std::istringstream in(test_support::read_file(path));
    std::string line, c;
    std::getline(in, line);
    std::vector<std::string> header;
    std::istringstream h(line);
    while (std::getline(h, c, ',')) header.push_back(c.substr(0, c.find("_[")));
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        for (std::size_t i = 0; std::getline(l, c, ','); ++i)
            columns[header.at(i)].push_back(std::stod(c));
    }
    return columns;
}

inline std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    REQUIRE_MESSAGE(it != names.end(), "no channel " << name);
    return static_cast<std::size_t>(it - names.begin());
}

} // namespace block_unsteady
