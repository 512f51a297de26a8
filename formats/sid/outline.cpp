#include "sid/outline.hpp"

#include <string>

namespace yamsc::sid {
namespace {

using diag::Kind;

constexpr const char* body_block_names[body_block_count] = {
    "mdCM", "J", "Ct", "Cr", "Me", "Gr", "Ge", "Oe", "ksigma", "Ke", "De"};

std::optional<BodyBlock> body_block(std::string_view name) {
    for (std::size_t i = 0; i < body_block_count; ++i) {
        if (same_name(name, body_block_names[i])) return static_cast<BodyBlock>(i);
    }
    return std::nullopt;
}

bool is_node_block(std::string_view name) {
    for (const char* known : {"origin", "phi", "psi", "AP", "sigma"}) {
        if (same_name(name, known)) return true;
    }
    return false;
}

bool is_taylor_key(std::string_view name) {
    for (const char* known :
         {"order", "nrow", "ncol", "nq", "nqn", "structure", "m0", "m1", "mn"}) {
        if (same_name(name, known)) return true;
    }
    return false;
}

bool is_refmod_key(std::string_view name) {
    return same_name(name, "mass") || same_name(name, "nelastq") || same_name(name, "ielastq");
}

/// The kinds of block; `unknown` is a block the reader skips.
enum class Ctx { part, modal, refmod, frame, node, taylor, unknown };

/// Whether `l` is something a block of kind `ctx` holds (known or wrongly written): a line
/// that belongs to an outer block tells that the inner one lacks its `end`.
bool is_item(Ctx ctx, const Line& l) {
    switch (ctx) {
    case Ctx::part:
        return l.shape == Line::Shape::open && same_name(l.name, "modal");
    case Ctx::modal:
        return (l.shape == Line::Shape::block &&
                (same_name(l.name, "refmod") || same_name(l.name, "frame") ||
                 body_block(l.name))) ||
               (l.shape == Line::Shape::open && same_name(l.name, "frame"));
    case Ctx::refmod:
        return l.is_key() && is_refmod_key(l.name);
    case Ctx::frame:
        return l.shape == Line::Shape::open && same_name(l.name, "node");
    case Ctx::node:
        return (l.shape == Line::Shape::assign && same_name(l.name, "rframe")) ||
               (l.shape == Line::Shape::block && is_node_block(l.name));
    case Ctx::taylor:
        return l.is_key() && is_taylor_key(l.name);
    case Ctx::unknown:
        return false;
    }
    return false;
}

std::string quoted(std::string_view name) {
    return "`" + std::string(name) + "`";
}

class Outliner {
public:
    Outliner(const std::vector<Line>& lines, ReadContext& cx) : lines_(lines), cx_(cx) {}

    SidOutline run() {
        SidOutline out;
        if (lines_.empty() || lines_.front().shape != Line::Shape::block ||
            !same_name(lines_.front().name, "part")) {
            cx_.error(Kind::MissingProperty, 1, 1,
                      "no line `part` in the file: an SID file is a block `part` ... `end part`");
            return out;
        }
        out.part = &lines_.front();
        read_part(out);
        out.truncated = eof_reported_;
        return out;
    }

private:
    struct OpenBlock {
        Ctx ctx;
        const Line* line;
    };

    /// Reads the lines of the block that `open` opens, up to its `end`. `on_item` takes the
    /// line at pos_ and returns true after consuming it, or false if the block does not hold
    /// it. Unknown blocks and keys are skipped with a warning.
    template <class OnItem> void read_block(Ctx ctx, const Line& open, OnItem&& on_item) {
        open_.push_back({ctx, &open});
        ++pos_;
        while (pos_ < lines_.size() && !cx_.gave_up()) {
            const Line& l = lines_[pos_];
            if (l.shape == Line::Shape::close && same_name(l.name, open.name)) {
                ++pos_;
                open_.pop_back();
                return;
            }
            if (on_item(l)) continue;
            if (belongs_to_outer(l)) {
                cx_.error(Kind::Syntax, l.line, l.col,
                          "block " + quoted(open.name) + " (line " + std::to_string(open.line) +
                              ") is not closed: expected `end " + std::string(open.name) +
                              "` before this line");
                open_.pop_back();
                return;
            }
            if (l.shape == Line::Shape::close) {
                cx_.error(Kind::Syntax, l.line, l.col,
                          "`end " + std::string(l.name) + "` closes no open block (the block " +
                              quoted(open.name) + " of line " + std::to_string(open.line) +
                              " is open)");
                ++pos_;
            } else if (l.shape == Line::Shape::block || l.shape == Line::Shape::open) {
                cx_.warning(Kind::UnknownProperty, l.line, l.col,
                            "unknown block " + quoted(l.name) + " in " + quoted(open.name) +
                                " is skipped");
                skip_unknown_block(l);
            } else {
                cx_.warning_once(std::string(open.name) + "/" + std::string(l.name),
                                 Kind::UnknownProperty, l.line, l.col,
                                 "unknown key " + quoted(l.name) + " in block " +
                                     quoted(open.name) + " is ignored");
                ++pos_;
            }
        }
        if (!eof_reported_ && !cx_.gave_up()) {
            cx_.error(Kind::Syntax, open.line, open.col,
                      "block " + quoted(open.name) + " is not closed: the file ends before `end " +
                          std::string(open.name) + "`");
            eof_reported_ = true; // the blocks around it are not closed either: one error
        }
        open_.pop_back();
    }

    /// Skips an unknown block up to its `end`, or up to a line that an enclosing block holds
    /// (then it was a lone line, not a block). Iterative: unknown blocks may nest deeply.
    void skip_unknown_block(const Line& open) {
        open_.push_back({Ctx::unknown, &open});
        ++pos_;
        int depth = 0;
        while (pos_ < lines_.size()) {
            const Line& l = lines_[pos_];
            if (l.shape == Line::Shape::close && same_name(l.name, open.name)) {
                ++pos_;
                if (depth-- == 0) break;
                continue;
            }
            if ((l.shape == Line::Shape::block || l.shape == Line::Shape::open) &&
                same_name(l.name, open.name)) {
                ++depth;
                ++pos_;
                continue;
            }
            if (belongs_to_outer(l)) break;
            ++pos_;
        }
        open_.pop_back();
    }

    bool belongs_to_outer(const Line& l) const {
        for (std::size_t i = 0; i + 1 < open_.size(); ++i) {
            const OpenBlock& b = open_[i];
            if (l.shape == Line::Shape::close && same_name(l.name, b.line->name)) return true;
            if (is_item(b.ctx, l)) return true;
        }
        return false;
    }

    void duplicate(const Line& again, const Line& first) {
        cx_.error(Kind::InvalidValue, again.line, again.col,
                  quoted(again.name) + " is given twice in this block (first at line " +
                      std::to_string(first.line) + ")");
    }

    /// Records a key that may be given once.
    void take_once(const Line*& slot, const Line& l) {
        if (slot != nullptr) {
            duplicate(l, *slot);
        } else {
            slot = &l;
        }
        ++pos_;
    }

    void read_part(SidOutline& out) {
        read_block(Ctx::part, *out.part, [&](const Line& l) {
            if (l.shape != Line::Shape::open || !same_name(l.name, "modal")) return false;
            if (out.modal != nullptr) {
                duplicate(l, *out.modal);
                SidOutline scratch;
                read_modal(l, scratch);
            } else {
                out.modal = &l;
                read_modal(l, out);
            }
            return true;
        });
    }

    void read_modal(const Line& open, SidOutline& out) {
        read_block(Ctx::modal, open, [&](const Line& l) {
            if (l.shape == Line::Shape::block && same_name(l.name, "refmod")) {
                if (out.refmod != nullptr) {
                    duplicate(l, *out.refmod);
                    SidOutline scratch;
                    read_refmod(l, scratch);
                } else {
                    out.refmod = &l;
                    read_refmod(l, out);
                }
                return true;
            }
            if ((l.shape == Line::Shape::open || l.shape == Line::Shape::block) &&
                same_name(l.name, "frame")) {
                if (out.frame != nullptr) {
                    duplicate(l, *out.frame);
                    SidOutline scratch;
                    read_frame(l, scratch);
                } else {
                    out.frame = &l;
                    read_frame(l, out);
                }
                return true;
            }
            if (l.shape != Line::Shape::block) return false;
            const std::optional<BodyBlock> block = body_block(l.name);
            if (!block) return false;
            read_taylor_into(out.body[static_cast<std::size_t>(*block)], l);
            return true;
        });
    }

    void read_refmod(const Line& open, SidOutline& out) {
        read_block(Ctx::refmod, open, [&](const Line& l) {
            if (l.shape == Line::Shape::assign && same_name(l.name, "mass")) {
                take_once(out.mass, l);
            } else if (l.shape == Line::Shape::assign && same_name(l.name, "nelastq")) {
                take_once(out.nelastq, l);
            } else if (l.shape == Line::Shape::indexed && same_name(l.name, "ielastq")) {
                out.mode_names.push_back(&l);
                ++pos_;
            } else if (l.is_key() && is_refmod_key(l.name)) {
                cx_.error(Kind::Syntax, l.line, l.col,
                          l.shape == Line::Shape::assign
                              ? quoted(l.name) + " needs an index: `ielastq(k) = name`"
                              : quoted(l.name) + " takes no index: `" + std::string(l.name) +
                                    " = value`");
                ++pos_;
            } else {
                return false;
            }
            return true;
        });
    }

    void read_frame(const Line& open, SidOutline& out) {
        read_block(Ctx::frame, open, [&](const Line& l) {
            if (l.shape != Line::Shape::open || !same_name(l.name, "node")) return false;
            if (out.nodes.size() >= static_cast<std::size_t>(Limits::max_nodes)) {
                if (out.nodes.size() == static_cast<std::size_t>(Limits::max_nodes)) {
                    cx_.error(Kind::Limit, l.line, l.col,
                              "more than " + std::to_string(Limits::max_nodes) + " nodes");
                }
                NodeOutline scratch;
                read_node(l, scratch);
                return true;
            }
            out.nodes.emplace_back();
            out.nodes.back().open = &l;
            read_node(l, out.nodes.back());
            return true;
        });
    }

    void read_node(const Line& open, NodeOutline& node) {
        read_block(Ctx::node, open, [&](const Line& l) {
            if (l.shape == Line::Shape::assign && same_name(l.name, "rframe")) {
                take_once(node.rframe, l);
                return true;
            }
            if (l.shape != Line::Shape::block) return false;
            if (same_name(l.name, "origin")) {
                read_taylor_into(node.origin, l);
            } else if (same_name(l.name, "phi")) {
                read_taylor_into(node.phi, l);
            } else if (same_name(l.name, "psi")) {
                read_taylor_into(node.psi, l);
            } else if (same_name(l.name, "AP")) {
                read_taylor_into(node.ap, l);
            } else if (same_name(l.name, "sigma")) {
                read_taylor_into(node.sigma, l);
            } else {
                return false;
            }
            return true;
        });
    }

    void read_taylor_into(std::optional<TaylorOutline>& slot, const Line& open) {
        if (slot) {
            duplicate(open, *slot->open);
            TaylorOutline scratch;
            read_taylor(open, scratch);
            return;
        }
        slot.emplace();
        read_taylor(open, *slot);
    }

    void read_taylor(const Line& open, TaylorOutline& t) {
        t.open = &open;
        read_block(Ctx::taylor, open, [&](const Line& l) {
            if (!l.is_key() || !is_taylor_key(l.name)) return false;
            const bool entry =
                same_name(l.name, "m0") || same_name(l.name, "m1") || same_name(l.name, "mn");
            if (entry != (l.shape == Line::Shape::indexed)) {
                cx_.error(Kind::Syntax, l.line, l.col,
                          entry ? quoted(l.name) + " needs indices: `" + std::string(l.name) +
                                      "(i, j) = value`"
                                : quoted(l.name) + " takes no index: `" + std::string(l.name) +
                                      " = value`");
                ++pos_;
                return true;
            }
            if (same_name(l.name, "mn")) {
                t.has_second_order = true;
                ++pos_;
            } else if (entry) {
                t.entries.push_back(&l);
                ++pos_;
            } else if (same_name(l.name, "order")) {
                take_once(t.order, l);
            } else if (same_name(l.name, "nrow")) {
                take_once(t.nrow, l);
            } else if (same_name(l.name, "ncol")) {
                take_once(t.ncol, l);
            } else if (same_name(l.name, "nqn")) {
                take_once(t.nqn, l);
            } else if (same_name(l.name, "nq")) {
                take_once(t.nq, l);
            } else {
                take_once(t.structure, l);
            }
            return true;
        });
    }

    const std::vector<Line>& lines_;
    ReadContext& cx_;
    std::size_t pos_ = 0;
    std::vector<OpenBlock> open_;
    bool eof_reported_ = false;
};

} // namespace

const char* body_block_name(BodyBlock block) {
    return body_block_names[static_cast<std::size_t>(block)];
}

SidOutline outline_sid(const std::vector<Line>& lines, ReadContext& cx) {
    return Outliner(lines, cx).run();
}

} // namespace yamsc::sid
