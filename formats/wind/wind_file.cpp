#include "wind/wind_file.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace yamsc::wind {

Samples read_wind_file(std::istream& in, const std::string& source) {
    Samples w;
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#' || line[first] == '!') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        s.imbue(std::locale::classic());
        double t = 0, v = 0;
        if (!(s >> t >> v)) {
            if (w.time.empty() && line_no == 1) continue; // the header
            throw std::runtime_error(source + ":" + std::to_string(line_no) +
                                     ": expected time and wind speed");
        }
        if (!w.time.empty() && !(t > w.time.back()))
            throw std::runtime_error(source + ":" + std::to_string(line_no) +
                                     ": times must increase");
        w.time.push_back(t);
        w.speed.push_back(v);
    }
    if (w.time.empty()) throw std::runtime_error(source + ": no wind samples");
    return w;
}

} // namespace yamsc::wind
