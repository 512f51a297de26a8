#pragma once
// `yamsc rotor-table DECK.fst`: the Cp/Ct/Cq table from the deck's rigid rotor.
#include "driver/commands.hpp"

#include <ostream>
#include <string>

namespace yamsc::analysis {

/// Whether rotor-table's argument is an OpenFAST deck (a `.fst`), not a table.
bool is_openfast_deck(const std::string& path);

int rotor_table_from_deck(const driver::RotorTableOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::analysis
