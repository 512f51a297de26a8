#include "sid/reader.hpp"

#include "sid/lines.hpp"
#include "sid/numbers.hpp"
#include "sid/outline.hpp"
#include "sid/taylor_builder.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <unordered_map>

namespace yamsc::sid {
namespace {

using diag::Kind;

std::string quoted(std::string_view name) {
    return "`" + std::string(name) + "`";
}

/// A free-text value as stored: a CR inside the line becomes a blank, as the writer writes it.
std::string text_of(std::string_view value) {
    std::string text(value);
    std::replace(text.begin(), text.end(), '\r', ' ');
    return text;
}

/// The third stage: the meaning of the outline, checked, as a Sid.
class Assembler {
public:
    Assembler(const SidOutline& outline, ReadContext& cx) : o_(outline), cx_(cx) {}

    std::optional<Sid> run() {
        // Reported by the outline; in a truncated file, missing blocks are no news.
        if (o_.part == nullptr || o_.truncated) return std::nullopt;
        if (o_.modal == nullptr) {
            cx_.error(Kind::MissingProperty, o_.part->line, o_.part->col,
                      "the part has no block `new modal`");
            return std::nullopt;
        }
        if (o_.refmod == nullptr) {
            cx_.error(Kind::MissingProperty, o_.modal->line, o_.modal->col,
                      "the body has no block `refmod` (it gives `mass` and `nelastq`)");
            return std::nullopt;
        }
        read_mass();
        if (!read_nq()) return std::nullopt;
        read_mode_names();
        read_nodes();
        read_body_blocks();
        return std::move(sid_);
    }

private:
    void read_mass() {
        const Line* mass = o_.mass;
        if (mass == nullptr) {
            cx_.error(Kind::MissingProperty, o_.refmod->line, o_.refmod->col,
                      "block `refmod` has no `mass`");
            return;
        }
        if (!mass->has_number()) {
            cx_.error(Kind::Syntax, mass->line, mass->value_col,
                      "expected a number after `mass =`, found '" + std::string(mass->value) + "'");
            return;
        }
        sid_.mass = parse_real(mass->value).value_or(NAN);
        if (!std::isfinite(sid_.mass) || sid_.mass < 0) {
            cx_.error(Kind::InvalidValue, mass->line, mass->value_col,
                      "the mass is '" + std::string(mass->value) +
                          "': it must be a finite number >= 0");
        }
    }

    bool read_nq() {
        const Line* n = o_.nelastq;
        if (n == nullptr) {
            cx_.error(Kind::MissingProperty, o_.refmod->line, o_.refmod->col,
                      "block `refmod` has no `nelastq` (the number of modes)");
            return false;
        }
        const long long value =
            n->value_kind == Line::ValueKind::integer ? parse_integer(n->value).value_or(-1) : -1;
        if (value < 0) {
            cx_.error(Kind::InvalidValue, n->line, n->value_col,
                      "`nelastq` must be a whole number >= 0, not '" + std::string(n->value) + "'");
            return false;
        }
        if (value > Limits::max_nq) {
            cx_.error(Kind::Limit, n->line, n->value_col,
                      "`nelastq` is " + std::string(n->value) + ": more than " +
                          std::to_string(Limits::max_nq) + " modes");
            return false;
        }
        sid_.nq = static_cast<int>(value);
        return true;
    }

    void read_mode_names() {
        sid_.mode_names.assign(static_cast<std::size_t>(sid_.nq), std::string());
        std::vector<const Line*> given(static_cast<std::size_t>(sid_.nq), nullptr);
        for (const Line* l : o_.mode_names) {
            if (cx_.gave_up()) return;
            const long long k = l->index[0];
            if (l->index_count != 1 || k < 1 || k > sid_.nq) {
                cx_.error(Kind::InvalidValue, l->line, l->col,
                          "`ielastq` takes one index, the mode 1.." + std::to_string(sid_.nq) +
                              " (nelastq = " + std::to_string(sid_.nq) + ")");
                continue;
            }
            const Line*& first = given[static_cast<std::size_t>(k - 1)];
            if (first != nullptr) {
                cx_.error(Kind::InvalidValue, l->line, l->col,
                          "`ielastq(" + std::to_string(k) + ")` is given twice (first at line " +
                              std::to_string(first->line) + ")");
                continue;
            }
            first = l;
            sid_.mode_names[static_cast<std::size_t>(k - 1)] = text_of(l->value);
        }
    }

    std::optional<Taylor> block(const std::optional<TaylorOutline>& outline, BlockShape shape) {
        if (!outline || cx_.gave_up()) return std::nullopt;
        return build_taylor(*outline, shape, sid_.nq, cx_);
    }

    void read_nodes() {
        std::unordered_map<long long, int> lines_of_ids;
        for (const NodeOutline& n : o_.nodes) {
            if (cx_.gave_up()) return;
            Node node;
            const Line& open = *n.open;
            const std::optional<long long> id = open.value_kind == Line::ValueKind::integer
                                                    ? parse_integer(open.value)
                                                    : std::nullopt;
            if (!id || *id < -2147483647LL || *id > 2147483647LL) {
                cx_.error(Kind::InvalidValue, open.line, open.value_col ? open.value_col : open.col,
                          "a node needs a whole number: `new node = 1`, not '" +
                              std::string(open.value) + "'");
            } else if (!lines_of_ids.emplace(*id, open.line).second) {
                cx_.error(Kind::InvalidValue, open.line, open.value_col,
                          "node " + std::to_string(*id) + " is given twice (first at line " +
                              std::to_string(lines_of_ids[*id]) + ")");
            } else {
                node.id = static_cast<int>(*id);
            }
            if (n.rframe != nullptr) node.rframe = text_of(n.rframe->value);
            read_node_blocks(n, node);
            sid_.nodes.push_back(std::move(node));
        }
    }

    void read_node_blocks(const NodeOutline& n, Node& node) {
        const Line& open = *n.open;
        const std::string which = "node " + std::string(open.value);
        if (!n.origin) {
            cx_.error(Kind::MissingProperty, open.line, open.col,
                      which + " has no block `origin` (its position)");
        } else if (auto t = block(n.origin, {3, 1, "3 x 1"})) {
            node.origin = std::move(*t);
        }
        node.phi = node_block_or_zero(n.phi, "phi", open, "its translations per mode");
        node.psi = node_block_or_zero(n.psi, "psi", open, "its rotations per mode");
        if (n.ap) {
            if (auto t = block(n.ap, {3, 3, "3 x 3"})) node.ap = std::move(*t);
        } else {
            cx_.warning_once("node/AP", Kind::MissingProperty, open.line, open.col,
                             which + " has no block `AP`: its axes are taken as the body's");
            node.ap = default_block(3, 3, 1, open, "AP");
            for (int i = 0; i < 3 && !node.ap.m0.empty(); ++i) node.ap.at0(i, i) = 1;
        }
        if (n.sigma) {
            if (auto t = block(n.sigma, {6, -1, "6 x ncol"})) {
                node.has_sigma = true;
                node.sigma = std::move(*t);
            }
        }
    }

    Taylor node_block_or_zero(const std::optional<TaylorOutline>& outline, const char* name,
                              const Line& open, const char* meaning) {
        const int nq = sid_.nq;
        if (outline) return block(outline, {3, nq, "3 x nq"}).value_or(Taylor{});
        cx_.warning_once(std::string("node/") + name, Kind::MissingProperty, open.line, open.col,
                         "node " + std::string(open.value) + " has no block `" + name +
                             "`: " + meaning + " are taken as zero");
        return default_block(3, nq, 0, open, name);
    }

    /// A block of order 0 for one the file leaves out. It counts against the budget of
    /// numbers like the blocks the file gives (a large nq makes large zero blocks); after an
    /// error nothing is allocated, as no SID will be returned.
    Taylor default_block(int nrow, int ncol, int structure, const Line& where, const char* name) {
        const std::size_t count = static_cast<std::size_t>(nrow) * static_cast<std::size_t>(ncol);
        if (cx_.errors() > 0) return Taylor{};
        if (!cx_.take_values(count)) {
            cx_.error(Kind::Limit, where.line, where.col,
                      "block " + quoted(name) + ", left out, would be " + std::to_string(nrow) +
                          " x " + std::to_string(ncol) +
                          " zeros: more numbers than the SID reader allows in all (" +
                          std::to_string(Limits::max_values) + ")");
            return Taylor{};
        }
        return Taylor::zeros(0, nrow, ncol, sid_.nq, structure);
    }

    void read_body_blocks() {
        const int nq = sid_.nq;
        struct Spec {
            BodyBlock which;
            Taylor Sid::*member;
            BlockShape shape;
            bool required;
            const char* meaning; // for a warning if it is left out; nullptr: no warning
        };
        const Spec specs[] = {
            {BodyBlock::mdCM, &Sid::md_cm, {3, 1, "3 x 1"}, true, nullptr},
            {BodyBlock::J, &Sid::J, {3, 3, "3 x 3"}, true, nullptr},
            {BodyBlock::Ct,
             &Sid::Ct,
             {nq, 3, "nq x 3"},
             false,
             "the coupling of the modes with translations is taken as zero"},
            {BodyBlock::Cr,
             &Sid::Cr,
             {nq, 3, "nq x 3"},
             false,
             "the coupling of the modes with rotations is taken as zero"},
            {BodyBlock::Me, &Sid::Me, {nq, nq, "nq x nq"}, true, nullptr},
            {BodyBlock::Gr, &Sid::Gr, {3, 3 * nq, "3 x 3nq"}, false, nullptr},
            {BodyBlock::Ge, &Sid::Ge, {nq, 3 * nq, "nq x 3nq"}, false, nullptr},
            {BodyBlock::Oe, &Sid::Oe, {nq, 6, "nq x 6"}, false, nullptr},
            {BodyBlock::ksigma, &Sid::ksigma, {nq, 1, "nq x 1"}, false, nullptr},
            {BodyBlock::Ke, &Sid::Ke, {nq, nq, "nq x nq"}, nq > 0, nullptr},
            {BodyBlock::De, &Sid::De, {nq, nq, "nq x nq"}, false, nullptr},
        };
        for (const Spec& spec : specs) {
            const auto& outline = o_.body[static_cast<std::size_t>(spec.which)];
            const char* name = body_block_name(spec.which);
            if (outline) {
                if (auto t = block(outline, spec.shape)) sid_.*spec.member = std::move(*t);
                continue;
            }
            if (spec.required) {
                cx_.error(Kind::MissingProperty, o_.modal->line, o_.modal->col,
                          "the body has no block " + quoted(name));
                continue;
            }
            if (spec.meaning != nullptr && nq > 0) {
                cx_.warning(Kind::MissingProperty, o_.modal->line, o_.modal->col,
                            "the body has no block " + quoted(name) + ": " + spec.meaning);
            }
            sid_.*spec.member = default_block(spec.shape.nrow, spec.shape.ncol, 0, *o_.modal, name);
        }
    }

    const SidOutline& o_;
    ReadContext& cx_;
    Sid sid_;
};

} // namespace

std::optional<Sid> read_sid(const std::shared_ptr<const diag::SourceFile>& file,
                            diag::Diagnostics& diags) {
    if (!file) throw diag::InternalError("read_sid called without a file");
    ReadContext cx(file, diags);
    try {
        if (file->text().size() > Limits::max_file_bytes) {
            cx.error(Kind::Limit, 0, 0,
                     "the SID file is too large (" + std::to_string(file->text().size()) +
                         " bytes; the limit is " + std::to_string(Limits::max_file_bytes >> 20) +
                         " MiB)");
            return std::nullopt;
        }
        const std::vector<Line> lines = split_lines(cx);
        const SidOutline outline = outline_sid(lines, cx);
        std::optional<Sid> sid = Assembler(outline, cx).run();
        if (cx.errors() > 0) return std::nullopt;
        return sid;
    } catch (const std::bad_alloc&) {
        diags.error(Kind::Limit, diag::Location{file, 0, 0},
                    "out of memory while reading the SID file");
    } catch (const std::length_error&) {
        diags.error(Kind::Limit, diag::Location{file, 0, 0},
                    "out of memory while reading the SID file");
    }
    return std::nullopt;
}

std::optional<Sid> read_sid_file(const std::string& path, diag::Diagnostics& diags) {
    std::error_code ec;
    const bool regular = std::filesystem::is_regular_file(path, ec);
    const std::uintmax_t size = regular ? std::filesystem::file_size(path, ec) : 0;
    std::ifstream in(path, std::ios::binary);
    if (!regular || ec || !in) {
        diags.error(Kind::Io, diag::Location{}, "cannot read the SID file '" + path + "'");
        return std::nullopt;
    }
    if (size > Limits::max_file_bytes) {
        diags.error(Kind::Limit, diag::Location{},
                    "the SID file '" + path + "' is too large (" + std::to_string(size) +
                        " bytes)");
        return std::nullopt;
    }
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        diags.error(Kind::Io, diag::Location{}, "cannot read the SID file '" + path + "'");
        return std::nullopt;
    }
    return read_sid(std::make_shared<const diag::SourceFile>(path, std::move(text)), diags);
}

} // namespace yamsc::sid
