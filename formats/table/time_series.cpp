// A time series by its file's kind (table.hpp).
#include "table/openfast_binary.hpp"
#include "table/table.hpp"

namespace yamsc::table {

Table read_time_series(const std::string& path) {
    const std::string suffix = ".outb";
    const bool binary = path.size() > suffix.size() &&
                        path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    return binary ? read_openfast_binary(path) : read_table(path);
}

} // namespace yamsc::table
