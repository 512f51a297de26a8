#pragma once
// What `yamsc fmu` compiles a unit's binary with: the headers and the static
// libraries of the FMI unit's runtime (libyamsc_fmi.a, libyamsc_runtime.a,
// libyamsc_files.a) and the shared libraries they need (SUNDIALS). Found as
// the derivation module is found (driver/derivation_loader.hpp): an installed
// tree relative to the program, so a moved install keeps working, then the
// build tree of this yamsc (the build tree first for a program still in it).
#include <string>
#include <vector>

namespace yamsc::analysis {

struct FmuToolchain {
    std::vector<std::string> include_dirs;    // yamsc's headers, then Eigen's
    std::vector<std::string> archives;        // linked whole: the FMI entry points
    std::vector<std::string> hidden_archives; // linked as needed, their symbols not exported
    /// A unit with blade elements links these too, before the hidden ones: the
    /// AeroDyn reader (libyamsc_aerodyn_input.a) and what it stands on; empty
    /// where this yamsc has none (installed under LIBDIR/yamsc/fmu/).
    std::vector<std::string> aerodyn_archives;
    std::vector<std::string> link_flags; // -L.. -lsundials_cvode .. -ldl
    std::string
        exports; // the linker's version script: the FMI functions are the unit's only symbols
};

/// The toolchain of this yamsc; throws diag::UserError naming the places tried
/// when the libraries are in none of them.
FmuToolchain fmu_toolchain();

} // namespace yamsc::analysis
