#include "sid/taylor_builder.hpp"

#include "sid/numbers.hpp"

#include <cmath>
#include <string>

namespace yamsc::sid {
namespace {

using diag::Kind;

std::string quoted(std::string_view name) {
    return "`" + std::string(name) + "`";
}

/// The entry as the file names it: `m1(1, 2, 3)`.
std::string entry_text(const Line& e) {
    std::string text(e.name);
    text += "(";
    for (int n = 0; n < e.index_count && n < 3; ++n) {
        if (n > 0) text += ", ";
        text += std::to_string(e.index[static_cast<std::size_t>(n)]);
    }
    return text + (e.index_count > 3 ? ", ...)" : ")");
}

class TaylorBuilder {
public:
    TaylorBuilder(const TaylorOutline& block, const BlockShape& shape, int nq, ReadContext& cx)
        : block_(block), shape_(shape), body_nq_(nq), cx_(cx), name_(quoted(block.open->name)) {}

    std::optional<Taylor> build() {
        const int errors_before = cx_.errors();
        if (!read_header() || !check_shape() || !allocate()) return std::nullopt;
        for (const Line* entry : block_.entries) {
            if (cx_.gave_up()) break;
            take_entry(*entry);
        }
        if (cx_.errors() > errors_before) return std::nullopt;
        return std::move(t_);
    }

private:
    /// A header key: a whole number in [low, high]; beyond `high` is a Limit error.
    bool header_key(const Line* key, const char* what, bool required, long long low, long long high,
                    int& out) {
        if (key == nullptr) {
            if (!required) return true;
            cx_.error(Kind::MissingProperty, block_.open->line, block_.open->col,
                      "block " + name_ + " has no `" + what + "`");
            return false;
        }
        if (key->value_kind != Line::ValueKind::integer) {
            cx_.error(Kind::InvalidValue, key->line, key->value_col,
                      std::string("`") + what + "` of block " + name_ +
                          " must be a whole number, not '" + std::string(key->value) + "'");
            return false;
        }
        const long long value = parse_integer(key->value).value_or(-1);
        if (std::string_view(what) == "structure" && (value < low || value > high)) {
            cx_.error(Kind::InvalidValue, key->line, key->value_col,
                      "unknown structure " + std::string(key->value) + " of block " + name_ +
                          " (0 zero, 1 diagonal, 2 symmetric, 3 full)");
            return false;
        }
        if (value < low || value > high) {
            cx_.error(value > high && high >= 1000 ? Kind::Limit : Kind::InvalidValue, key->line,
                      key->value_col,
                      std::string("`") + what + "` of block " + name_ + " is " +
                          std::string(key->value) + "; it must be " + std::to_string(low) + " to " +
                          std::to_string(high));
            return false;
        }
        out = static_cast<int>(value);
        return true;
    }

    bool read_header() {
        bool ok = header_key(block_.order, "order", true, 0, 2, t_.order);
        ok = header_key(block_.nrow, "nrow", true, 0, Limits::max_dimension, t_.nrow) && ok;
        ok = header_key(block_.ncol, "ncol", true, 0, Limits::max_dimension, t_.ncol) && ok;
        ok = header_key(block_.nq, "nq", t_.order == 1, 0, Limits::max_nq, t_.nq) && ok;
        ok = header_key(block_.nqn, "nqn", false, 0, Limits::max_nq, t_.nqn) && ok;
        ok = header_key(block_.structure, "structure", true, 0, 3, t_.structure) && ok;
        if (ok && t_.order == 2) {
            cx_.error(Kind::NotSupported, block_.order->line, block_.order->value_col,
                      "block " + name_ +
                          " has order 2: second-order Taylor terms (`mn`) are not supported");
            return false;
        }
        if (ok && block_.has_second_order) {
            cx_.warning_once("mn", Kind::NotSupported, block_.open->line, block_.open->col,
                             "`mn` entries of block " + name_ +
                                 " are ignored: they belong to order 2");
        }
        return ok;
    }

    bool check_shape() {
        if ((t_.structure == 1 || t_.structure == 2) && t_.nrow != t_.ncol) {
            cx_.error(Kind::InvalidValue, block_.structure->line, block_.structure->value_col,
                      "block " + name_ + " is " + std::to_string(t_.nrow) + " x " +
                          std::to_string(t_.ncol) + ": a " +
                          (t_.structure == 1 ? "diagonal" : "symmetric") + " block (structure " +
                          std::to_string(t_.structure) + ") must be square");
            return false;
        }
        if (t_.nrow != shape_.nrow || (shape_.ncol >= 0 && t_.ncol != shape_.ncol)) {
            const std::string must =
                shape_.ncol >= 0 ? std::to_string(shape_.nrow) + " x " + std::to_string(shape_.ncol)
                                 : std::to_string(shape_.nrow) + " rows";
            cx_.error(Kind::InvalidValue, block_.open->line, block_.open->col,
                      "block " + name_ + " is " + std::to_string(t_.nrow) + " x " +
                          std::to_string(t_.ncol) + "; it must be " + shape_.text + " = " + must);
            return false;
        }
        // Tools write nq = 0 in blocks of order 0, whose size does not depend on nq.
        if (t_.nq != body_nq_ && (t_.order == 1 || t_.nq != 0)) {
            const Line* at = block_.nq != nullptr ? block_.nq : block_.open;
            cx_.error(Kind::InvalidValue, at->line, at == block_.open ? at->col : at->value_col,
                      "block " + name_ + " has nq = " + std::to_string(t_.nq) +
                          " but the body has nelastq = " + std::to_string(body_nq_) + " modes");
            return false;
        }
        return true;
    }

    bool allocate() {
        const std::size_t cells =
            static_cast<std::size_t>(t_.nrow) * static_cast<std::size_t>(t_.ncol);
        const std::size_t count =
            cells * (t_.order == 1 ? 1 + static_cast<std::size_t>(t_.nq) : std::size_t{1});
        if (!cx_.take_values(count)) {
            cx_.error(Kind::Limit, block_.open->line, block_.open->col,
                      "block " + name_ + " holds " + std::to_string(count) +
                          " numbers: more than the SID reader allows in all (" +
                          std::to_string(Limits::max_values) + ")");
            return false;
        }
        const int nqn = t_.nqn;
        t_ = Taylor::zeros(t_.order, t_.nrow, t_.ncol, t_.nq, t_.structure);
        t_.nqn = nqn;
        given_.assign(t_.m0.size() + t_.m1.size(), 0);
        return true;
    }

    /// Checks an index against 1..size; `what` names it for the message.
    bool in_range(const Line& e, std::size_t n, long long size, const char* what) {
        const long long value = e.index[n];
        if (value >= 1 && value <= size) return true;
        std::string message = entry_text(e) + ": " + what + " " + std::to_string(value) +
                              " is out of range 1.." + std::to_string(size) + " of block " + name_;
        if (same_name(e.name, "m1")) message += " (yamsc reads `m1(row, column, mode)`)";
        cx_.error(Kind::InvalidValue, e.line, e.col, message);
        return false;
    }

    void take_entry(const Line& e) {
        const bool first_order = same_name(e.name, "m1");
        const int wanted = first_order ? 3 : 2;
        if (first_order && t_.order != 1) {
            cx_.error(Kind::InvalidValue, e.line, e.col,
                      entry_text(e) + ": block " + name_ +
                          " has order 0, so it has no first-order entries `m1`");
            return;
        }
        if (e.index_count != wanted) {
            cx_.error(Kind::InvalidValue, e.line, e.col,
                      entry_text(e) + ": `" + std::string(e.name) + "` takes " +
                          std::to_string(wanted) + " indices" +
                          (first_order ? " (row, column, mode)" : " (row, column)"));
            return;
        }
        if (!e.has_number()) {
            cx_.error(Kind::Syntax, e.line, e.value_col,
                      "expected a number after `" + entry_text(e) + " =`, found '" +
                          std::string(e.value) + "'");
            return;
        }
        const double value = parse_real(e.value).value_or(NAN);
        if (!std::isfinite(value)) {
            cx_.error(Kind::InvalidValue, e.line, e.value_col,
                      entry_text(e) + " of block " + name_ + " is '" + std::string(e.value) +
                          "': not a finite number");
            return;
        }
        const bool ok = in_range(e, 0, t_.nrow, "row") && in_range(e, 1, t_.ncol, "column") &&
                        (!first_order || in_range(e, 2, t_.nq, "mode"));
        if (!ok) return;
        const int i = static_cast<int>(e.index[0]) - 1;
        const int j = static_cast<int>(e.index[1]) - 1;
        const int k = first_order ? static_cast<int>(e.index[2]) - 1 : -1;
        if (value != 0 && (t_.structure == 0 || (t_.structure == 1 && i != j))) {
            cx_.error(Kind::InvalidValue, e.line, e.value_col,
                      entry_text(e) + " = " + std::string(e.value) + " lies outside the " +
                          (t_.structure == 0 ? "all-zero" : "diagonal") + " structure " +
                          std::to_string(t_.structure) + " of block " + name_);
            return;
        }
        set(e, i, j, k, value);
        if (t_.structure == 2 && i != j) set(e, j, i, k, value);
    }

    void set(const Line& e, int i, int j, int k, double value) {
        const std::size_t cell = static_cast<std::size_t>(i * t_.ncol + j);
        const std::size_t slot =
            k < 0 ? cell : t_.m0.size() + cell * static_cast<std::size_t>(t_.nq) + k;
        double& target = k < 0 ? t_.at0(i, j) : t_.at1(i, j, k);
        if (given_[slot] != 0 && target != value) {
            cx_.error(
                Kind::InvalidValue, e.line, e.col,
                entry_text(e) + " of block " + name_ + " is given twice" +
                    (t_.structure == 2 ? " (a symmetric block lists (i, j) and (j, i) once)" : "") +
                    " with different values");
            return;
        }
        given_[slot] = 1;
        target = value;
    }

    const TaylorOutline& block_;
    const BlockShape& shape_;
    int body_nq_;
    ReadContext& cx_;
    std::string name_;
    Taylor t_;
    std::vector<unsigned char> given_; // which numbers an entry set (m0, then m1)
};

} // namespace

std::optional<Taylor> build_taylor(const TaylorOutline& block, const BlockShape& shape, int nq,
                                   ReadContext& cx) {
    return TaylorBuilder(block, shape, nq, cx).build();
}

} // namespace yamsc::sid
