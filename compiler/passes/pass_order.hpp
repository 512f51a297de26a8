#pragma once
// What each pass adds to an ir::System and what it needs, as a table: every
// pass calls enter() first, which checks its prerequisites against the passes
// the System records and records it. A pass run out of order is an internal
// error, not rows silently derived from the wrong equations.
#include "ir/system.hpp"

namespace yamsc::passes {

struct PassInfo {
    ir::Pass pass;
    const char* name;
    const char* adds;   // the System's fields it fills, for messages and docs
    ir::PassSet needs;  // must have run before
    ir::PassSet before; // must not have run yet (they read what this pass changes)
    bool repeats;       // may run more than once (one `approx` group per run)
};

/// The row of `pass`.
const PassInfo& pass_info(ir::Pass pass);

/// Records that `pass` runs on `s`. Throws diag::InternalError when a pass it
/// needs has not run, a pass it must precede has, or it ran already (and
/// does not repeat).
void enter(ir::System& s, ir::Pass pass);

} // namespace yamsc::passes
