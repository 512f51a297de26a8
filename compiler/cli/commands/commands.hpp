#pragma once
// The entries of the command table (command_table.cpp), one function per
// command, defined in the file of its group.
#include "cli/command.hpp"

namespace yamsc::cli {

Command compile_command();       // compile.cpp
Command check_command();         // check_eval.cpp
Command eval_command();          // check_eval.cpp
Command sim_command();           // sim.cpp
Command batch_command();         // batch.cpp
Command batch_merge_command();   // batch.cpp
Command lin_command();           // lin_trim.cpp
Command trim_command();          // lin_trim.cpp
Command from_openfast_command(); // from_openfast.cpp
Command rotor_table_command();   // rotor_table.cpp
Command sid_command();           // sid.cpp
Command loads_command();         // loads.cpp
Command turbulence_command();    // turbulence.cpp
Command dlc_command();           // dlc.cpp
Command view_command();          // view.cpp
Command fmu_command();           // fmu.cpp

} // namespace yamsc::cli
