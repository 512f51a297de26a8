#pragma once
// The commands that run models (driver/commands.hpp: their options, and what
// every command promises about `out`, `err` and its exit status).
#include "driver/commands.hpp"

#include <iosfwd>

namespace yamsc::analysis {

int eval_compiled(const driver::EvalOptions& o, std::ostream& out, std::ostream& err);
int lin(const driver::LinOptions& o, std::ostream& out, std::ostream& err);
int trim(const driver::TrimOptions& o, std::ostream& out, std::ostream& err);
int sim(const driver::SimOptions& o, std::ostream& out, std::ostream& err);
int batch(const driver::BatchOptions& o, std::ostream& out, std::ostream& err);
int batch_merge(const driver::BatchMergeOptions& o, std::ostream& out, std::ostream& err);
int rotor_table(const driver::RotorTableOptions& o, std::ostream& out, std::ostream& err);
int fmu(const driver::FmuOptions& o, std::ostream& out, std::ostream& err);
int turbulence(const driver::TurbulenceOptions& o, std::ostream& out, std::ostream& err);
int view(const driver::ViewOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::analysis
