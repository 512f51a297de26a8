#pragma once
// A minimal JSON writer for the CLI's machine-readable outputs.
#include <string>
#include <vector>

namespace yamsc::driver::json {

std::string quote(const std::string& s);
std::string number(double v); // shortest round-trip form; NaN/inf as null
std::string array(const std::vector<double>& v);
std::string matrix(const std::vector<std::vector<double>>& m);
std::string strings(const std::vector<std::string>& v);

} // namespace yamsc::driver::json
