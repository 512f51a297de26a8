#pragma once
// ASCII case for the keys and section names of the input files yamsc reads
// (OpenFAST's, MAP++'s, MoorDyn's): their readers compare them without case,
// as the Fortran readers do, and a locale must not change the result.
#include <string>
#include <string_view>

namespace yamsc::text {

/// `s` with a-z as A-Z; every other byte as it is.
std::string ascii_upper(std::string_view s);

} // namespace yamsc::text
