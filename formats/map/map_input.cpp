#include "map/map_input.hpp"

#include "text/ascii.hpp"

#include "elastodyn/file.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace yamsc::map {
namespace {

using diag::Kind;

struct Word {
    std::string_view text;
    int col = 0;
};

struct Row {
    int line = 0;
    std::vector<Word> words;
};

// MAP++ splits its rows on blanks and tabs only.
std::vector<Word> split(std::string_view line) {
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start)
            words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return words;
}

enum Section { dictionary, nodes, lines, options, sections };
constexpr const char* section_names[sections] = {"LINE DICTIONARY", "NODE PROPERTIES",
                                                 "LINE PROPERTIES", "SOLVER OPTIONS"};

class Reader {
public:
    Reader(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags)
        : file_(file), diags_(diags) {}

    std::optional<MapInput> read() {
        std::vector<Row> rows[sections];
        if (!split_sections(rows)) return std::nullopt;
        MapInput in;
        in.file = file_;
        for (const Row& r : rows[dictionary]) read_line_type(r, in);
        for (const Row& r : rows[nodes]) read_node(r, in);
        for (const Row& r : rows[lines]) read_line(r, in);
        for (const Row& r : rows[options]) read_option(r, in);
        if (!errors_) check_references(in);
        if (errors_) return std::nullopt;
        return in;
    }

private:
    diag::Location at(int line, int col = 1) const { return {file_, line, col}; }
    diag::Location at(const Row& r, std::size_t word) const {
        return at(r.line, word < r.words.size() ? r.words[word].col : 1);
    }
    void error(Kind kind, diag::Location where, std::string message) {
        ++errors_;
        diags_.error(kind, std::move(where), std::move(message));
    }

    // As MAP++: the first three lines of each section (its '-' line, the column
    // names, the units) are skipped, and a line starting with '-' after them
    // starts the next section; every other line of SOLVER OPTIONS not
    // starting with '!' is an option.
    bool split_sections(std::vector<Row> (&rows)[sections]) {
        int section = dictionary, within = 0;
        int count = 0;
        const int n = file_->line_count();
        for (int line = 1; line <= n; ++line) {
            const std::string_view text = file_->line(line);
            ++within;
            if (within >= 4 && section != options && !text.empty() && text[0] == '-') {
                ++section;
                within = 1;
                continue;
            }
            if (within < 4) continue;
            if (section == options && !text.empty() && text[0] == '!') continue;
            Row r{line, split(text)};
            if (r.words.empty()) continue;
            if (++count > max_rows * sections) {
                error(Kind::Limit, at(line),
                      "more than " + std::to_string(max_rows) +
                          " rows in a section of a MAP++ file");
                return false;
            }
            rows[section].push_back(std::move(r));
        }
        if (section < options) {
            error(Kind::MissingProperty, at(n),
                  std::string("the MAP++ file ends before its ") + section_names[section + 1] +
                      " section (each section starts with a line of '-')");
            return false;
        }
        return true;
    }

    bool enough(const Row& r, std::size_t count, const char* what) {
        if (r.words.size() >= count) return true;
        error(Kind::InvalidValue, at(r.line, 1),
              std::string("a ") + what + " row needs " + std::to_string(count) + " values, found " +
                  std::to_string(r.words.size()));
        return false;
    }

    std::optional<double> number(const Row& r, std::size_t word, const char* column) {
        const auto v = elastodyn::parse_number(r.words[word].text);
        if (!v) {
            error(Kind::InvalidValue, at(r, word),
                  std::string(column) + " is not a number: '" + std::string(r.words[word].text) +
                      "'");
        }
        return v;
    }

    std::optional<int> count(const Row& r, std::size_t word, const char* column) {
        const auto v = number(r, word, column);
        if (!v) return std::nullopt;
        // The range first: converting a double outside int's range is undefined.
        if (!(*v >= 1 && *v <= max_rows) || *v != std::floor(*v)) {
            error(Kind::InvalidValue, at(r, word),
                  std::string(column) + " must be a whole number from 1 to " +
                      std::to_string(max_rows));
            return std::nullopt;
        }
        return static_cast<int>(*v);
    }

    void read_line_type(const Row& r, MapInput& in) {
        if (!enough(r, 5, "LINE DICTIONARY")) return;
        LineType t;
        t.label = std::string(r.words[0].text);
        t.at = at(r, 0);
        const char* names[] = {"Diam", "MassDenInAir", "EA", "CB"};
        double* fields[] = {&t.diameter, &t.mass_density, &t.axial_stiffness, &t.seabed_friction};
        for (int k = 0; k < 4; ++k) {
            const auto v = number(r, 1 + k, names[k]);
            if (!v) return;
            *fields[k] = *v;
        }
        if (!(t.diameter > 0) || !(t.axial_stiffness > 0) || !(t.mass_density > 0))
            error(Kind::InvalidValue, at(r, 1),
                  "a line type's diameter, mass density and EA must be positive");
        for (const LineType& other : in.line_types)
            if (text::ascii_upper(other.label) == text::ascii_upper(t.label))
                error(Kind::DuplicateName, t.at, "line type '" + t.label + "' is defined twice");
        in.line_types.push_back(t);
    }

    std::optional<NodeValue> node_value(const Row& r, std::size_t word, const char* column,
                                        bool depth_allowed) {
        std::string_view text = r.words[word].text;
        NodeValue v;
        if (text::ascii_upper(text) == "DEPTH") {
            if (!depth_allowed) {
                error(
                    Kind::InvalidValue, at(r, word),
                    std::string("`depth` (the water depth) is only for a Fix node's Z, not for ") +
                        (std::string(column) == "Z" ? "another node's" : column));
                return std::nullopt;
            }
            v.depth = true;
            return v;
        }
        if (!text.empty() && text[0] == '#') {
            v.guess = true;
            text.remove_prefix(1);
            if (text.empty()) return v; // '#' alone: MAP++ solves for it from zero
        }
        const auto x = elastodyn::parse_number(text);
        if (!x) {
            error(Kind::InvalidValue, at(r, word),
                  std::string(column) + " is not a number: '" + std::string(r.words[word].text) +
                      "'");
            return std::nullopt;
        }
        v.value = *x;
        return v;
    }

    void read_node(const Row& r, MapInput& in) {
        ++node_rows_;
        if (!enough(r, 10, "NODE PROPERTIES")) return;
        Node n;
        n.at = at(r, 0);
        const auto number = count(r, 0, "Node");
        if (!number) return;
        n.number = *number;
        const std::string type = text::ascii_upper(r.words[1].text);
        if (type == "FIX" || type == "FIXED")
            n.kind = NodeKind::fix;
        else if (type == "VESSEL")
            n.kind = NodeKind::vessel;
        else if (type == "CONNECT")
            n.kind = NodeKind::connect;
        else {
            error(Kind::InvalidValue, at(r, 1),
                  "unknown node type '" + std::string(r.words[1].text) +
                      "' (Fix, Vessel or Connect)" +
                      diag::did_you_mean(r.words[1].text, {"Fix", "Vessel", "Connect"}));
            return;
        }
        const char* names[] = {"X", "Y", "Z", "M", "B", "FX", "FY", "FZ"};
        NodeValue* fields[] = {&n.x,        &n.y,       &n.z,       &n.mass,
                               &n.buoyancy, &n.force_x, &n.force_y, &n.force_z};
        for (int k = 0; k < 8; ++k) {
            const auto v = node_value(r, 2 + k, names[k], k == 2 && n.kind == NodeKind::fix);
            if (!v) return;
            *fields[k] = *v;
        }
        if (n.number != node_rows_)
            error(Kind::InvalidValue, n.at,
                  "node " + std::to_string(n.number) + " is out of order: expected node " +
                      std::to_string(node_rows_));
        in.nodes.push_back(n);
    }

    void read_line(const Row& r, MapInput& in) {
        ++line_rows_;
        if (!enough(r, 5, "LINE PROPERTIES")) return;
        LineRow l;
        l.at = at(r, 0);
        l.type_at = at(r, 1);
        l.anchor_at = at(r, 3);
        l.fairlead_at = at(r, 4);
        const auto number = count(r, 0, "Line");
        const auto length = number ? this->number(r, 2, "UnstrLen") : std::nullopt;
        const auto anchor = length ? count(r, 3, "NodeAnch") : std::nullopt;
        const auto fairlead = anchor ? count(r, 4, "NodeFair") : std::nullopt;
        if (!fairlead) return;
        l.number = *number;
        l.type = std::string(r.words[1].text);
        l.unstretched_length = *length;
        l.anchor_node = *anchor;
        l.fairlead_node = *fairlead;
        for (std::size_t k = 5; k < r.words.size(); ++k) l.flags.emplace_back(r.words[k].text);
        if (!(l.unstretched_length > 0))
            error(Kind::InvalidValue, at(r, 2), "a line's unstretched length must be positive");
        if (l.number != line_rows_)
            error(Kind::InvalidValue, l.at,
                  "line " + std::to_string(l.number) + " is out of order: expected line " +
                      std::to_string(line_rows_));
        in.lines.push_back(l);
    }

    void read_option(const Row& r, MapInput& in) {
        static const std::vector<std::string> known = {
            "HELP",          "INNER_FTOL", "INNER_GTOL",    "INNER_XTOL",         "INNER_MAX_ITS",
            "OUTER_MAX_ITS", "OUTER_TOL",  "OUTER_EPSILON", "INTEGRATION_DT",     "KB_DEFAULT",
            "CB_DEFAULT",    "OUTER_CD",   "OUTER_BD",      "OUTER_FD",           "WAVE_KINEMATICS",
            "LM_MODEL",      "POWELL",     "PG_COOKED",     "KRYLOV_ACCELERATOR", "REPEAT",
            "REF_POSITION"};
        SolverOption o;
        o.name = text::ascii_upper(r.words[0].text);
        o.at = at(r, 0);
        for (std::size_t k = 1; k < r.words.size(); ++k) o.values.emplace_back(r.words[k].text);
        if (std::find(known.begin(), known.end(), o.name) == known.end()) {
            diags_.warning(Kind::UnknownProperty, o.at,
                           "unknown MAP++ solver option '" + std::string(r.words[0].text) +
                               "' (ignored)" + diag::did_you_mean(o.name, known));
        }
        if (o.name == "REPEAT") {
            in.repeat_at = o.at;
            if (r.words.size() > max_repeat_angles + 1) {
                error(Kind::Limit, o.at,
                      "more than " + std::to_string(max_repeat_angles) + " REPEAT angles");
                return;
            }
            for (std::size_t k = 1; k < r.words.size(); ++k) {
                const auto angle = number(r, k, "a REPEAT angle");
                if (angle) in.repeat_angles.push_back(*angle);
            }
        }
        in.options.push_back(std::move(o));
    }

    void check_references(const MapInput& in) {
        for (const LineRow& l : in.lines) {
            const bool typed =
                std::any_of(in.line_types.begin(), in.line_types.end(), [&](const LineType& t) {
                    return text::ascii_upper(t.label) == text::ascii_upper(l.type);
                });
            if (!typed) {
                std::vector<std::string> labels;
                for (const LineType& t : in.line_types) labels.push_back(t.label);
                error(Kind::UnknownName, l.type_at,
                      "unknown line type '" + l.type + "'" + diag::did_you_mean(l.type, labels));
            }
            const int nodes = static_cast<int>(in.nodes.size());
            if (l.anchor_node > nodes)
                error(Kind::UnknownName, l.anchor_at,
                      "no node " + std::to_string(l.anchor_node) + " (the file has " +
                          std::to_string(nodes) + ")");
            if (l.fairlead_node > nodes)
                error(Kind::UnknownName, l.fairlead_at,
                      "no node " + std::to_string(l.fairlead_node) + " (the file has " +
                          std::to_string(nodes) + ")");
            if (l.anchor_node == l.fairlead_node)
                error(Kind::InvalidValue, l.fairlead_at, "a line's two ends are the same node");
        }
    }

    std::shared_ptr<const diag::SourceFile> file_;
    diag::Diagnostics& diags_;
    int errors_ = 0;
    int node_rows_ = 0, line_rows_ = 0; // rows read so far, with errors or not
};

} // namespace

std::optional<MapInput> read_map_input(const std::shared_ptr<const diag::SourceFile>& file,
                                       diag::Diagnostics& diags) {
    return Reader(file, diags).read();
}

} // namespace yamsc::map
