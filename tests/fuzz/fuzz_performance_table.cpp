// libFuzzer target: a rotor performance table (formats/performance_table, ROSCO's
// Cp_Ct_Cq format) through its reader. Properties: no crash, no sanitizer report; a
// rejected file throws std::runtime_error only; an accepted one has rising pitch and
// TSR vectors of 2 entries or more and three full matrices of finite numbers.
#include "performance_table/performance_table.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

bool rising(const std::vector<double>& v) {
    if (v.size() < 2) return false;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1])) return false;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc::performance_table;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    Table t;
    try {
        t = read_performance_table(in, "fuzz.txt");
    } catch (const std::runtime_error&) {
        return 0;
    }
    if (!rising(t.pitch_deg) || !rising(t.tsr)) std::abort();
    for (const std::vector<double>* m : {&t.cp, &t.ct, &t.cq}) {
        if (m->size() != t.tsr.size() * t.pitch_deg.size()) std::abort();
        for (double v : *m)
            if (!std::isfinite(v)) std::abort();
    }
    return 0;
}
