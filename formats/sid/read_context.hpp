#pragma once
// What every stage of the SID reader shares: the file, the diagnostics, the limits that keep a
// hostile file from exhausting memory or time, and the budget of numbers it may allocate.
#include "diag/diagnostics.hpp"

#include <cstddef>
#include <memory>
#include <set>
#include <string>

namespace yamsc::sid {

struct Limits {
    static constexpr std::size_t max_file_bytes = std::size_t{256} << 20;
    /// Lines that say something (64 bytes each once split): a FEM body with 1000 nodes and 30
    /// modes has about 3 million.
    static constexpr std::size_t max_lines = std::size_t{8} << 20;
    static constexpr int max_nq = 10000;
    static constexpr int max_nodes = 100000;
    /// Rows or columns of one block (Gr and Ge have 3 nq columns).
    static constexpr int max_dimension = 3 * max_nq;
    /// Numbers all blocks together may hold (a file may declare a large block that it leaves
    /// zero, so the size of the file does not bound this): 2^25 doubles, 256 MiB.
    static constexpr std::size_t max_values = std::size_t{1} << 25;
    /// After this many errors the reader stops: the rest would be noise.
    static constexpr int max_errors = 100;
};

class ReadContext {
public:
    ReadContext(std::shared_ptr<const diag::SourceFile> file, diag::Diagnostics& diags)
        : file_(std::move(file)), diags_(diags) {}

    const std::shared_ptr<const diag::SourceFile>& file() const { return file_; }
    diag::Location at(int line, int col) const { return diag::Location{file_, line, col}; }

    void error(diag::Kind kind, int line, int col, std::string message);
    void warning(diag::Kind kind, int line, int col, std::string message);
    /// Warns once per `topic` (e.g. an unknown key that a tool writes in every block).
    void warning_once(const std::string& topic, diag::Kind kind, int line, int col,
                      std::string message);

    int errors() const { return errors_; }
    /// True once max_errors errors were reported: every loop of the reader stops.
    bool gave_up() const { return errors_ >= Limits::max_errors; }

    /// Takes `count` numbers from the allocation budget; false (and nothing taken) if the
    /// budget does not hold them.
    bool take_values(std::size_t count);

private:
    std::shared_ptr<const diag::SourceFile> file_;
    diag::Diagnostics& diags_;
    int errors_ = 0;
    std::size_t values_left_ = Limits::max_values;
    std::set<std::string> warned_;
};

} // namespace yamsc::sid
