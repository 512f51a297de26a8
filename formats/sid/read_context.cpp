#include "sid/read_context.hpp"

namespace yamsc::sid {

void ReadContext::error(diag::Kind kind, int line, int col, std::string message) {
    if (gave_up()) return;
    ++errors_;
    diags_.error(kind, at(line, col), std::move(message));
    if (gave_up()) {
        diags_.error(diag::Kind::Limit, at(line, col),
                     "too many errors in this SID file (" + std::to_string(Limits::max_errors) +
                         "); stopping here");
    }
}

void ReadContext::warning(diag::Kind kind, int line, int col, std::string message) {
    if (gave_up()) return;
    diags_.warning(kind, at(line, col), std::move(message));
}

void ReadContext::warning_once(const std::string& topic, diag::Kind kind, int line, int col,
                               std::string message) {
    if (!warned_.insert(topic).second) return;
    warning(kind, line, col, std::move(message) + " (reported once)");
}

bool ReadContext::take_values(std::size_t count) {
    if (count > values_left_) return false;
    values_left_ -= count;
    return true;
}

} // namespace yamsc::sid
