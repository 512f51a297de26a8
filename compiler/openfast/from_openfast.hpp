#pragma once
// `yamsc from-openfast` (driver/commands.hpp: its options, and what every
// command promises about `out`, `err` and its exit status).
#include "driver/commands.hpp"

#include <iosfwd>

namespace yamsc::openfast {

int from_openfast(const driver::FromOpenFastOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::openfast
