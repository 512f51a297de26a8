#include "moordyn/moordyn_input.hpp"

#include "text/ascii.hpp"

#include "elastodyn/file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

namespace yamsc::moordyn {
namespace {

using diag::Kind;

struct Word {
    std::string_view text;
    int col = 0;
};

struct Row {
    int line = 0;
    std::string_view text;
    std::vector<Word> words;
};

// Fortran's list-directed reads split at blanks, tabs and commas.
bool separator(char c) {
    return c == ' ' || c == '\t' || c == ',' || c == '\r';
}

std::vector<Word> split(std::string_view line) {
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && separator(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !separator(line[i])) ++i;
        if (i > start)
            words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return words;
}

bool contains(const std::string& text, const char* what) {
    return text.find(what) != std::string::npos;
}

enum class Section {
    none,
    line_types,
    rod_types,
    bodies,
    rods,
    points,
    lines,
    skipped, // EXTERNAL LOADS, CONTROL, FAILURE
    options,
    outputs
};

// MoorDyn's tests of a header line, in its order (the first that matches wins).
Section section_of(const std::string& header) {
    if (contains(header, "LINE DICTIONARY") || contains(header, "LINE TYPES"))
        return Section::line_types;
    if (contains(header, "ROD DICTIONARY") || contains(header, "ROD TYPES"))
        return Section::rod_types;
    if (contains(header, "BODIES") || contains(header, "BODY LIST") ||
        contains(header, "BODY PROPERTIES"))
        return Section::bodies;
    if (contains(header, "RODS") || contains(header, "ROD LIST") ||
        contains(header, "ROD PROPERTIES"))
        return Section::rods;
    if (contains(header, "POINTS") || contains(header, "CONNECTION PROPERTIES") ||
        contains(header, "NODE PROPERTIES") || contains(header, "POINT PROPERTIES") ||
        contains(header, "POINT LIST"))
        return Section::points;
    if (contains(header, "LINES") || contains(header, "LINE PROPERTIES") ||
        contains(header, "LINE LIST"))
        return Section::lines;
    if (contains(header, "EXTERNAL LOADS") || contains(header, "CONTROL") ||
        contains(header, "FAILURE"))
        return Section::skipped;
    if (contains(header, "OPTIONS")) return Section::options;
    if (contains(header, "OUTPUT")) return Section::outputs;
    return Section::none;
}

bool is_table(Section s) {
    return s == Section::line_types || s == Section::rod_types || s == Section::bodies ||
           s == Section::rods || s == Section::points || s == Section::lines;
}

// MoorDyn's DecomposeString: letters, a number, letters (upper case).
struct Decomposed {
    std::string letters, digits, rest;
};

Decomposed decompose(std::string_view word) {
    const std::string u = text::ascii_upper(word);
    Decomposed d;
    std::size_t i = 0;
    while (i < u.size() && !std::isdigit(static_cast<unsigned char>(u[i]))) ++i;
    d.letters = u.substr(0, i);
    const std::size_t start = i;
    while (i < u.size() && std::isdigit(static_cast<unsigned char>(u[i]))) ++i;
    d.digits = u.substr(start, i - start);
    d.rest = u.substr(i);
    return d;
}

const std::vector<std::string> known_options = {"WRITELOG",   "DTM",
                                                "TSCHEME",    "G",
                                                "RHOW",       "RHO",
                                                "WTRDPTH",    "DEPTH",
                                                "WATERDEPTH", "KBOT",
                                                "KB",         "CBOT",
                                                "CB",         "DTIC",
                                                "TMAXIC",     "CDSCALEIC",
                                                "THRESHIC",   "WATERKIN",
                                                "DTOUT",      "MU_KT",
                                                "MU_KA",      "MC",
                                                "CV",         "FRICDAMP",
                                                "INERTIALF",  "INERTIALF_RAMPT",
                                                "OUTSWITCH",  "DISABLEOUTTIME"};

class Reader {
public:
    Reader(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags)
        : file_(file), diags_(diags) {}

    std::optional<MoorDynInput> read() {
        in_.file = file_;
        in_.options_at = {file_, 0, 0};
        Section section = Section::none;
        int to_skip = 0; // a table's column names and units
        const int n = file_->line_count();
        if (n > 20 * max_rows) {
            error(Kind::Limit, at(1),
                  "a MoorDyn file of more than " + std::to_string(20 * max_rows) + " lines");
            return std::nullopt;
        }
        for (int line = 1; line <= n; ++line) {
            const std::string_view text = file_->line(line);
            Row r{line, text, split(text)};
            // ProcessComFile drops blank lines and comments.
            if (r.words.empty() || text[0] == '!' || text[0] == '#' || text[0] == '%') continue;
            const std::string u = text::ascii_upper(text);
            if (contains(u, "---")) {
                check_count();
                section = section_of(u);
                to_skip = is_table(section) ? 2 : 0;
                if (section == Section::skipped)
                    diags_.warning(Kind::NotSupported, at(line),
                                   "this MoorDyn section is not read (external loads, control "
                                   "and failures act on MoorDyn's dynamic lines only)");
                if (section == Section::options) in_.options_at = at(line, r.words[0].col);
                continue;
            }
            if (to_skip == 2 && is_table(section) && r.words.size() >= 2 &&
                (text::ascii_upper(r.words[1].text) == "NTYPES" ||
                 text::ascii_upper(r.words[1].text) == "NCONNECTS" ||
                 text::ascii_upper(r.words[1].text) == "NLINES")) {
                // MoorDyn v1: the table's length before its column names.
                in_.layout = 1;
                const auto count = whole(r.words[0].text, at(r, 0), std::string(r.words[1].text));
                if (!count) return std::nullopt;
                announced_ = *count;
                announced_at_ = at(r, 0);
                continue;
            }
            if (to_skip > 0) {
                --to_skip;
                continue;
            }
            if (section == Section::outputs && contains(u, "END")) section = Section::none;
            // v1 ends its options with END too.
            if (section == Section::options && in_.layout == 1 && r.words.size() == 1 &&
                text::ascii_upper(r.words[0].text) == "END")
                section = Section::none;
            if (!row(section, r)) return std::nullopt;
        }
        check_count();
        if (!errors_) check_references();
        if (errors_) return std::nullopt;
        return std::move(in_);
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

    // A v1 table holds as many rows as its count line says.
    void check_count() {
        if (announced_ >= 0 && table_rows_ != announced_)
            error(Kind::InvalidValue, announced_at_,
                  "the table announces " + std::to_string(announced_) + " rows and holds " +
                      std::to_string(table_rows_));
        announced_ = -1;
        table_rows_ = 0;
    }

    // One row of a section; false after a limit (reading stops there).
    bool row(Section section, const Row& r) {
        if (is_table(section)) ++table_rows_;
        std::size_t count = 0;
        switch (section) {
        case Section::line_types:
            read_line_type(r);
            count = in_.line_types.size();
            break;
        case Section::rod_types:
            count = other(r, in_.rod_types);
            break;
        case Section::bodies:
            count = other(r, in_.bodies);
            break;
        case Section::rods:
            count = other(r, in_.rods);
            break;
        case Section::points:
            read_point(r);
            count = point_rows_;
            break;
        case Section::lines:
            read_line(r);
            count = in_.lines.size();
            break;
        case Section::options:
            read_option(r);
            count = in_.options.size();
            break;
        case Section::outputs:
            for (const Word& w : r.words) in_.outputs.emplace_back(w.text);
            count = in_.outputs.size();
            break;
        case Section::none:
        case Section::skipped:
            break;
        }
        if (count <= static_cast<std::size_t>(max_rows)) return true;
        error(Kind::Limit, at(r.line),
              "more than " + std::to_string(max_rows) + " entries in a section of a MoorDyn file");
        return false;
    }

    bool enough(const Row& r, std::size_t count, const char* what) {
        if (r.words.size() >= count) return true;
        error(Kind::InvalidValue, at(r.line, r.words[0].col),
              std::string("a ") + what + " row needs " + std::to_string(count) + " values, found " +
                  std::to_string(r.words.size()));
        return false;
    }

    std::optional<double> number(const Row& r, std::size_t word, const std::string& column,
                                 const std::string& entry) {
        const auto v = elastodyn::parse_number(r.words[word].text);
        if (!v || !std::isfinite(*v)) {
            error(Kind::InvalidValue, at(r, word),
                  column + " of " + entry + " is not a number: '" +
                      std::string(r.words[word].text) + "'");
            return std::nullopt;
        }
        return v;
    }

    std::optional<int> whole(std::string_view text, diag::Location where,
                             const std::string& column) {
        const auto v = elastodyn::parse_number(text);
        // The range first: converting a double outside int's range is undefined.
        if (!v || !(*v >= 1 && *v <= max_rows) || *v != std::floor(*v)) {
            error(Kind::InvalidValue, std::move(where),
                  column + " must be a whole number from 1 to " + std::to_string(max_rows) + ": '" +
                      std::string(text) + "'");
            return std::nullopt;
        }
        return static_cast<int>(*v);
    }

    // EA (and BA) may be bar-separated: EA|EA_D[|...] for MoorDyn's visco-elastic
    // lines; the first value is the static stiffness.
    std::optional<double> first_of_bars(const Row& r, std::size_t word, const std::string& column,
                                        const std::string& entry, int* values) {
        const std::string_view text = r.words[word].text;
        const std::size_t bar = text.find('|');
        if (values) *values = 1 + static_cast<int>(std::count(text.begin(), text.end(), '|'));
        const auto v = elastodyn::parse_number(text.substr(0, bar));
        if (!v || !std::isfinite(*v)) {
            error(Kind::InvalidValue, at(r, word),
                  column + " of " + entry + " is not a number: '" + std::string(text) +
                      "' (tables of nonlinear " + column + " from a file are not read)");
            return std::nullopt;
        }
        return v;
    }

    void read_line_type(const Row& r) {
        const std::size_t n = r.words.size();
        if (in_.layout == 1) {
            read_line_type_v1(r);
            return;
        }
        if (n != 10 && n != 11 && n != 13) {
            error(Kind::InvalidValue, at(r, 0),
                  "a LINE TYPES row has 10, 11 or 13 values (Name Diam MassDen EA BA/-zeta EI Cd "
                  "Ca CdAx CaAx [Cl [dF cF]]), found " +
                      std::to_string(n));
            return;
        }
        LineType t;
        t.name = std::string(r.words[0].text);
        t.at = at(r, 0);
        const std::string entry = "line type '" + t.name + "'";
        const auto d = number(r, 1, "Diam", entry);
        const auto m = d ? number(r, 2, "MassDen", entry) : std::nullopt;
        const auto ea = m ? first_of_bars(r, 3, "EA", entry, &t.stiffness_values) : std::nullopt;
        const auto ba = ea ? first_of_bars(r, 4, "BA/-zeta", entry, nullptr) : std::nullopt;
        if (!ba) return;
        if (t.stiffness_values > 3) {
            error(Kind::InvalidValue, at(r, 3), "EA of " + entry + " has at most 3 values");
            return;
        }
        const char* names[] = {"EI", "Cd", "Ca", "CdAx", "CaAx", "Cl"};
        double* fields[] = {&t.bending_stiffness, &t.drag_normal,      &t.added_mass_normal,
                            &t.drag_axial,        &t.added_mass_axial, &t.lift};
        for (std::size_t k = 0; k < 6 && 5 + k < n; ++k) {
            const auto v = number(r, 5 + k, names[k], entry);
            if (!v) return;
            *fields[k] = *v;
        }
        t.diameter = *d;
        t.mass_density = *m;
        t.axial_stiffness = *ea;
        t.internal_damping = *ba;
        add_line_type(std::move(t), r);
    }

    void read_line_type_v1(const Row& r) {
        if (!enough(r, 9, "LINE TYPES (v1: Name Diam MassDen EA BA/-zeta Can Cat Cdn Cdt)")) return;
        LineType t;
        t.name = std::string(r.words[0].text);
        t.at = at(r, 0);
        const std::string entry = "line type '" + t.name + "'";
        const char* names[] = {"Diam", "MassDen", "EA", "BA/-zeta", "Can", "Cat", "Cdn", "Cdt"};
        double* fields[] = {&t.diameter,         &t.mass_density,      &t.axial_stiffness,
                            &t.internal_damping, &t.added_mass_normal, &t.added_mass_axial,
                            &t.drag_normal,      &t.drag_axial};
        for (std::size_t k = 0; k < 8; ++k) {
            const auto v = number(r, 1 + k, names[k], entry);
            if (!v) return;
            *fields[k] = *v;
        }
        add_line_type(std::move(t), r);
    }

    void add_line_type(LineType t, const Row& r) {
        const std::string entry = "line type '" + t.name + "'";
        if (!(t.diameter > 0) || !(t.mass_density > 0) || !(t.axial_stiffness > 0))
            error(Kind::InvalidValue, at(r, 1),
                  "the diameter, mass density and EA of " + entry + " must be positive");
        for (const LineType& other : in_.line_types)
            if (other.name == t.name) error(Kind::DuplicateName, t.at, entry + " is defined twice");
        in_.line_types.push_back(std::move(t));
    }

    std::size_t other(const Row& r, std::vector<OtherRow>& rows) {
        rows.push_back({std::string(r.words[0].text), at(r, 0)});
        return rows.size();
    }

    std::optional<Attachment> attachment(const Row& r, int* attached_to) {
        const Decomposed d = decompose(r.words[1].text);
        const std::string& a = d.letters;
        const bool plain = d.digits.empty() && d.rest.empty();
        if (plain && (a == "FIXED" || a == "FIX" || a == "ANCHOR")) return Attachment::fixed;
        if (plain && (a == "VESSEL" || a == "VES" || a == "COUPLED" || a == "CPLD"))
            return Attachment::coupled;
        if (plain && (a == "FREE" || a == "POINT" || a == "P" || a == "CONNECT"))
            return Attachment::free;
        if ((a == "BODY" || a == "TURBINE" || a == "T") && d.rest.empty() && !d.digits.empty()) {
            const auto n = whole(d.digits, at(r, 1), "the number of " + a);
            if (!n) return std::nullopt;
            *attached_to = *n;
            return a == "BODY" ? Attachment::body : Attachment::turbine;
        }
        error(Kind::InvalidValue, at(r, 1),
              "unknown attachment '" + std::string(r.words[1].text) + "' of point " +
                  std::string(r.words[0].text) +
                  " (Fixed, Vessel, Coupled, Free, Body<n> or Turbine<n>)" +
                  diag::did_you_mean(r.words[1].text,
                                     {"Fixed", "Vessel", "Coupled", "Free", "Body1"}));
        return std::nullopt;
    }

    void read_point(const Row& r) {
        ++point_rows_;
        const bool v1 = in_.layout == 1;
        if (v1 && r.words.size() < 12) {
            error(Kind::InvalidValue, at(r, 0),
                  "a CONNECTION PROPERTIES row (v1) has 12 values (Node Type X Y Z M V FX FY FZ "
                  "CdA CA), found " +
                      std::to_string(r.words.size()));
            return;
        }
        if (!v1 && r.words.size() != 9) {
            error(Kind::InvalidValue, at(r, 0),
                  "a POINTS row has 9 values (ID Attachment X Y Z M V CdA Ca), found " +
                      std::to_string(r.words.size()));
            return;
        }
        Point p;
        p.at = at(r, 0);
        p.attachment_at = at(r, 1);
        p.z_at = at(r, 4);
        const auto id = whole(r.words[0].text, at(r, 0), "a point's ID");
        if (!id) return;
        p.id = *id;
        const std::string entry = "point " + std::to_string(p.id);
        const auto kind = attachment(r, &p.attached_to);
        if (!kind) return;
        p.attachment = *kind;
        const std::string z = text::ascii_upper(r.words[4].text);
        if (contains(z, "SEABED") || contains(z, "GROUND") || contains(z, "FLOOR")) {
            p.on_seabed = true;
        }
        const char* names[] = {"X", "Y", "Z", "M", "V", "CdA", "Ca", "FX", "FY", "FZ"};
        double* fields[] = {&p.x,         &p.y,          &p.z,        &p.mass,     &p.volume,
                            &p.drag_area, &p.added_mass, &p.force[0], &p.force[1], &p.force[2]};
        // v1's columns: X Y Z M V FX FY FZ CdA CA
        const std::size_t v1_words[] = {2, 3, 4, 5, 6, 10, 11, 7, 8, 9};
        for (std::size_t k = 0; k < (v1 ? 10u : 7u); ++k) {
            if (k == 2 && p.on_seabed) continue;
            const auto v = number(r, v1 ? v1_words[k] : 2 + k, names[k], entry);
            if (!v) return;
            *fields[k] = *v;
        }
        if (static_cast<std::size_t>(p.id) != point_rows_)
            error(Kind::InvalidValue, p.at,
                  "point " + std::to_string(p.id) +
                      " is out of order: MoorDyn numbers its points 1, 2, ... (expected " +
                      std::to_string(point_rows_) + ")");
        in_.points.push_back(std::move(p));
    }

    std::optional<End> end(const Row& r, std::size_t word, const std::string& entry) {
        const Decomposed d = decompose(r.words[word].text);
        End e;
        e.at = at(r, word);
        const bool point = d.letters.empty() || d.letters == "P" || d.letters == "POINT";
        const bool rod = d.letters == "R" || d.letters == "ROD";
        if (!d.digits.empty() &&
            ((point && d.rest.empty()) || (rod && (d.rest == "A" || d.rest == "B")))) {
            const auto n = whole(d.digits, e.at, "the point or rod of " + entry);
            if (!n) return std::nullopt;
            e.rod = rod;
            e.number = *n;
            e.rod_end = rod ? d.rest[0] : 0;
            return e;
        }
        error(Kind::InvalidValue, e.at,
              "the end of " + entry +
                  " is neither a point (3, P3, Point3) nor a rod's end "
                  "(R2A, Rod2B): '" +
                  std::string(r.words[word].text) + "'");
        return std::nullopt;
    }

    void read_line(const Row& r) {
        if (!enough(r, 7, "LINES")) return;
        LineRow l;
        l.at = at(r, 0);
        l.type_at = at(r, 1);
        const auto id = whole(r.words[0].text, at(r, 0), "a line's ID");
        if (!id) return;
        l.id = *id;
        const std::string entry = "line " + std::to_string(l.id);
        // v1: ID LineType UnstrLen NumSegs NodeAnch NodeFair; v2: ID LineType AttachA
        // AttachB UnstrLen NumSegs.
        const bool v1 = in_.layout == 1;
        const std::size_t a_word = v1 ? 4 : 2, b_word = v1 ? 5 : 3;
        const std::size_t length_word = v1 ? 2 : 4, segments_word = v1 ? 3 : 5;
        const auto a = end(r, a_word, entry);
        const auto b = a ? end(r, b_word, entry) : std::nullopt;
        const auto length = b ? number(r, length_word, "UnstrLen", entry) : std::nullopt;
        const auto segments =
            length ? whole(r.words[segments_word].text, at(r, segments_word), "NumSegs of " + entry)
                   : std::nullopt;
        if (!segments) return;
        l.type = std::string(r.words[1].text);
        l.end_a = *a;
        l.end_b = *b;
        l.unstretched_length = *length;
        l.segments = *segments;
        l.outputs = std::string(r.words[6].text);
        if (!(l.unstretched_length > 0))
            error(Kind::InvalidValue, at(r, length_word),
                  "the unstretched length of " + entry + " must be positive");
        for (const LineRow& other : in_.lines)
            if (other.id == l.id) error(Kind::DuplicateName, l.at, entry + " is defined twice");
        in_.lines.push_back(std::move(l));
    }

    void read_option(const Row& r) {
        if (r.words.size() < 2) {
            error(Kind::InvalidValue, at(r, 0),
                  "an OPTIONS row is a value and its name, found only '" +
                      std::string(r.words[0].text) + "'");
            return;
        }
        Option o;
        o.value = std::string(r.words[0].text);
        o.name = text::ascii_upper(r.words[1].text);
        o.at = at(r, 1);
        if (std::find(known_options.begin(), known_options.end(), o.name) == known_options.end()) {
            diags_.warning(Kind::UnknownProperty, o.at,
                           "unknown MoorDyn option '" + std::string(r.words[1].text) +
                               "' (ignored)" + diag::did_you_mean(o.name, known_options));
            in_.options.push_back(std::move(o));
            return;
        }
        const bool text = o.name == "TSCHEME" || o.name == "WATERKIN";
        const bool depth = o.name == "WTRDPTH" || o.name == "DEPTH" || o.name == "WATERDEPTH";
        if (depth && o.value.find_first_of("abcdfghijklmnopqrstuvwxyzABCDFGHIJKLMNOPQRSTUVWXYZ") !=
                         std::string::npos) {
            error(Kind::NotSupported, at(r, 0),
                  "a bathymetry file as the water depth is not read: '" + o.value + "'");
            return;
        }
        std::optional<double> v;
        if (!text) {
            v = number(r, 0, "the value", "option " + std::string(r.words[1].text));
            if (!v) return;
        }
        if (o.name == "G") in_.gravity = v;
        if (o.name == "RHOW" || o.name == "RHO") in_.water_density = v;
        if (depth) {
            in_.water_depth = v;
            in_.water_depth_at = at(r, 0);
        }
        if (o.name == "DTM") in_.time_step = v;
        if (o.name == "KBOT" || o.name == "KB") in_.seabed_stiffness = *v;
        if (o.name == "CBOT" || o.name == "CB") in_.seabed_damping = *v;
        in_.options.push_back(std::move(o));
    }

    void check_references() {
        std::vector<std::string> names;
        for (const LineType& t : in_.line_types) names.push_back(t.name);
        for (const LineRow& l : in_.lines) {
            if (std::find(names.begin(), names.end(), l.type) == names.end())
                error(Kind::UnknownName, l.type_at,
                      "unknown line type '" + l.type + "' of line " + std::to_string(l.id) +
                          diag::did_you_mean(l.type, names));
            for (const End* e : {&l.end_a, &l.end_b}) {
                const std::size_t have = e->rod ? in_.rods.size() : in_.points.size();
                if (static_cast<std::size_t>(e->number) > have)
                    error(Kind::UnknownName, e->at,
                          std::string("no ") + (e->rod ? "rod " : "point ") +
                              std::to_string(e->number) + " for line " + std::to_string(l.id) +
                              " (the file has " + std::to_string(have) + ")");
            }
            if (!l.end_a.rod && !l.end_b.rod && l.end_a.number == l.end_b.number)
                error(Kind::InvalidValue, l.end_b.at,
                      "the two ends of line " + std::to_string(l.id) + " are the same point");
        }
        for (const Point& p : in_.points) {
            const std::size_t have = p.attachment == Attachment::body ? in_.bodies.size() : 0;
            if (p.attachment == Attachment::body && static_cast<std::size_t>(p.attached_to) > have)
                error(Kind::UnknownName, p.attachment_at,
                      "no body " + std::to_string(p.attached_to) + " for point " +
                          std::to_string(p.id) + " (the file has " + std::to_string(have) + ")");
        }
    }

    std::shared_ptr<const diag::SourceFile> file_;
    diag::Diagnostics& diags_;
    MoorDynInput in_;
    int errors_ = 0;
    std::size_t point_rows_ = 0; // rows read so far, with errors or not
    int table_rows_ = 0;         // rows of the current table
    int announced_ = -1;         // its v1 count, -1 without one
    diag::Location announced_at_;
};

} // namespace

std::optional<MoorDynInput> read_moordyn_input(const std::shared_ptr<const diag::SourceFile>& file,
                                               diag::Diagnostics& diags) {
    return Reader(file, diags).read();
}

} // namespace yamsc::moordyn
