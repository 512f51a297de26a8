#pragma once
// How a routine's statements are laid out in functions. Compilers take time
// superlinear in the size of a function (register allocation over one huge
// basic block), so a routine with more statements than a limit is cut into
// part functions of at most that many statements, run in order by the main
// function. Temporaries used by a later part travel in a work array `w`
// whose slots are reused once their value is dead.
#include "codegen/module.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

struct Statement {
    enum class Kind { define, assign, factor, solve, sweep, call } kind = Kind::define;
    int expr = 0;                           // define: the temporary's expression
    const Assignment* assignment = nullptr; // assign
    const Step* step = nullptr;             // factor, solve, sweep, call
    int part = -1; // define, assign: the part function; -1 when the routine is not cut
};

struct BodyPlan {
    std::vector<Statement> statements; // in execution order
    int part_count = 0;                // 0: one function, no parts
    std::vector<int> slot;             // by temporary number: its w slot, or -1 (a local)
    int slot_count = 0;
    /// By part: the names (arguments, locals, "w") its statements read or write.
    std::vector<std::vector<std::string>> names_used;
};

/// `max_statements` <= 0: never cut.
BodyPlan plan_body(const Routine& routine, int max_statements);

} // namespace yamsc::codegen
