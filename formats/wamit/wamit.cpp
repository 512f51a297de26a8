#include "wamit/wamit.hpp"

#include "elastodyn/file.hpp"

#include <cmath>
#include <string>
#include <string_view>

namespace yamsc::wamit {
namespace {

using diag::Kind;

struct Word {
    std::string_view text;
    int col = 0;
};

// Fortran's list input separates values by blanks, tabs and commas.
std::vector<Word> split(std::string_view line) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; };
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !blank(line[i])) ++i;
        if (i > start)
            words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return words;
}

/// The rows of one file: each line's values checked as numbers, mode indices
/// as whole numbers in range; `parse` fills a row from them.
class Rows {
public:
    Rows(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags,
         const char* what)
        : file_(file), diags_(diags), what_(what) {}

    /// Calls row(line, values) for each non-blank line with min..max values.
    template <class F> bool each(std::size_t min, std::size_t max, F&& row) {
        int count = 0;
        for (int line = 1; line <= file_->line_count(); ++line) {
            words_ = split(file_->line(line));
            if (words_.empty()) continue;
            if (++count > max_rows) {
                error(line, 1, "more than " + std::to_string(max_rows) + " rows in a " + what_);
                return false;
            }
            if (words_.size() < min || words_.size() > max) {
                const Word& w = words_.size() > max ? words_[max] : words_.back();
                const int col =
                    words_.size() > max ? w.col : w.col + static_cast<int>(w.text.size());
                error(line, col,
                      std::string("a row of a ") + what_ + " has " +
                          (min == max ? std::to_string(min)
                                      : std::to_string(min) + " or " + std::to_string(max)) +
                          " values, found " + std::to_string(words_.size()));
                continue;
            }
            values_.assign(words_.size(), 0.0);
            bool ok = true;
            for (std::size_t k = 0; k < words_.size(); ++k) {
                const auto v = elastodyn::parse_number(words_[k].text);
                if (!v) {
                    error(line, words_[k].col,
                          "'" + std::string(words_[k].text) + "' is not a number");
                    ok = false;
                } else {
                    values_[k] = *v;
                }
            }
            if (ok) row(line);
        }
        if (count == 0 && errors_ == 0) error(1, 1, std::string("the ") + what_ + " has no rows");
        return errors_ == 0;
    }

    double value(std::size_t k) const { return values_[k]; }
    std::size_t size() const { return values_.size(); }

    /// Value k as a mode index, or 0 after an error.
    int mode(int line, std::size_t k) {
        const double v = values_[k];
        // The range first: converting a double outside int's range is undefined.
        if (!(v >= 1 && v <= max_mode) || v != std::floor(v)) {
            error(line, words_[k].col,
                  "a mode index must be a whole number from 1 to " + std::to_string(max_mode) +
                      ", not '" + std::string(words_[k].text) + "'");
            return 0;
        }
        return static_cast<int>(v);
    }

    void error(int line, int col, std::string message) {
        ++errors_;
        diags_.error(Kind::InvalidValue, {file_, line, col}, std::move(message));
    }
    int col(std::size_t k) const { return words_[k].col; }

private:
    std::shared_ptr<const diag::SourceFile> file_;
    diag::Diagnostics& diags_;
    const char* what_;
    std::vector<Word> words_;
    std::vector<double> values_;
    int errors_ = 0;
};

} // namespace

std::optional<RadiationFile> read_radiation(const std::shared_ptr<const diag::SourceFile>& file,
                                            diag::Diagnostics& diags) {
    RadiationFile out{file, {}};
    Rows rows(file, diags, "WAMIT .1 file (PER I J A B)");
    const bool ok = rows.each(4, 5, [&](int line) {
        RadiationRow r;
        r.period = rows.value(0);
        r.i = rows.mode(line, 1);
        r.j = rows.mode(line, 2);
        r.added_mass = rows.value(3);
        if (rows.size() == 5) r.damping = rows.value(4);
        r.line = line;
        // The limits (PER <= 0) carry A alone; HydroDyn ignores a B written there.
        if (r.period > 0 && !r.damping)
            rows.error(line, rows.col(3), "a row of a positive period needs its damping B after A");
        if (r.period <= 0) r.damping.reset();
        if (r.i && r.j) out.rows.push_back(r);
    });
    if (!ok) return std::nullopt;
    return out;
}

std::optional<ExcitationFile> read_excitation(const std::shared_ptr<const diag::SourceFile>& file,
                                              diag::Diagnostics& diags) {
    ExcitationFile out{file, {}};
    Rows rows(file, diags, "WAMIT .3 file (PER BETA I |X| PHASE Re Im)");
    const bool ok = rows.each(7, 7, [&](int line) {
        ExcitationRow r;
        r.period = rows.value(0);
        r.heading = rows.value(1);
        r.i = rows.mode(line, 2);
        r.modulus = rows.value(3);
        r.phase = rows.value(4);
        r.re = rows.value(5);
        r.im = rows.value(6);
        r.line = line;
        // WAMIT writes the excitation at finite, positive periods only.
        if (!(r.period > 0)) rows.error(line, rows.col(0), "a .3 row needs a positive period");
        if (r.i) out.rows.push_back(r);
    });
    if (!ok) return std::nullopt;
    return out;
}

std::optional<HydrostaticFile>
read_hydrostatics(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags) {
    HydrostaticFile out{file, {}};
    Rows rows(file, diags, "WAMIT .hst file (I J C)");
    const bool ok = rows.each(3, 3, [&](int line) {
        HydrostaticRow r;
        r.i = rows.mode(line, 0);
        r.j = rows.mode(line, 1);
        r.restoring = rows.value(2);
        r.line = line;
        if (r.i && r.j) out.rows.push_back(r);
    });
    if (!ok) return std::nullopt;
    return out;
}

} // namespace yamsc::wamit
