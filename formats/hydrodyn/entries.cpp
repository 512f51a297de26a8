#include "hydrodyn/entries.hpp"

#include "hydrodyn/hydrodyn_input.hpp"

#include <cctype>
#include <cmath>

namespace yamsc::hydrodyn {

using aerodyn::Entry;
using diag::Kind;

diag::Location entry_location(const std::vector<std::pair<std::string, diag::Location>>& entries,
                              const std::shared_ptr<const diag::SourceFile>& file,
                              const std::string& key) {
    for (const auto& [name, at] : entries)
        if (elastodyn::same_key(name, key)) return at;
    return diag::Location{file, 0, 0};
}

diag::Location Input::location(const std::string& key) const {
    return entry_location(entries, file, key);
}

diag::Location Values::at(std::size_t i) const {
    return line->at(static_cast<int>(std::min(i, tokens.size())));
}

std::optional<bool> parse_logical(std::string_view v) {
    if (!v.empty() && v[0] == '.') v.remove_prefix(1);
    if (!v.empty() && (v[0] == 't' || v[0] == 'T')) return true;
    if (!v.empty() && (v[0] == 'f' || v[0] == 'F')) return false;
    return std::nullopt;
}

std::optional<Entry> EntryReader::seen(std::optional<Entry> e) {
    if (e) where_.emplace_back(e->key, e->at());
    return e;
}

std::optional<Entry> EntryReader::need(const char* key) {
    return seen(c_.expect(key));
}
std::optional<Entry> EntryReader::maybe(const char* key) {
    return seen(c_.take(key));
}

void EntryReader::set(const std::optional<Entry>& e, bool& v) {
    if (e)
        if (auto x = c_.flag(*e)) v = *x;
}
void EntryReader::set(const std::optional<Entry>& e, int& v) {
    if (e)
        if (auto x = c_.integer(*e)) v = *x;
}
void EntryReader::set(const std::optional<Entry>& e, double& v) {
    if (e)
        if (auto x = c_.number(*e)) v = *x;
}
void EntryReader::set(const std::optional<Entry>& e, std::string& v) {
    if (e) v = e->value();
}
void EntryReader::set_or_default(const std::optional<Entry>& e, std::optional<double>& v) {
    bool bad = false;
    if (e) v = c_.number_or_default(*e, bad);
}

std::optional<int> EntryReader::count(const char* key, int low, int high) {
    auto e = need(key);
    if (!e) return std::nullopt;
    auto n = c_.integer(*e);
    if (!n) return std::nullopt;
    if (*n < low || *n > high) {
        diags().error(Kind::Limit, e->at(),
                      "'" + e->key + "' must be " + std::to_string(low) + " to " +
                          std::to_string(high) + " (it is " + std::to_string(*n) + ")");
        return std::nullopt;
    }
    return n;
}

std::size_t EntryReader::leading_numbers() {
    const aerodyn::Line* l = c_.peek();
    if (!l) return 0;
    std::size_t n = 0;
    while (n < l->tokens.size() && elastodyn::parse_number(l->tokens[n].text)) ++n;
    return n;
}

std::optional<Values> EntryReader::row(const std::string& what, std::size_t n, const char* key) {
    if (!c_.peek()) {
        c_.next(what); // reports the end of the file
        return std::nullopt;
    }
    const aerodyn::Line* l = c_.next(what);
    if (!l) return std::nullopt;
    last_row_ = l;
    if (l->tokens.size() < n) {
        diags().error(Kind::MissingProperty, l->at(static_cast<int>(l->tokens.size())),
                      what + ": " + std::to_string(n) + " values expected, this line holds " +
                          std::to_string(l->tokens.size()));
        return std::nullopt;
    }
    Values v{l, {l->tokens.begin(), l->tokens.begin() + static_cast<std::ptrdiff_t>(n)}};
    if (key && l->tokens.size() > n && elastodyn::same_key(l->tokens[n].text, key))
        where_.emplace_back(l->tokens[n].text, v.at(0));
    return v;
}

std::optional<std::vector<double>> EntryReader::numbers(const std::string& what, std::size_t n,
                                                        const char* key) {
    auto v = row(what, n, key);
    if (!v) return std::nullopt;
    std::vector<double> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto x = number(*v, i, what);
        if (!x) return std::nullopt; // one error a row: the rest follows from it
        out.push_back(*x);
    }
    return out;
}

bool EntryReader::next_holds(std::size_t n, const char* key) {
    const aerodyn::Line* l = c_.peek();
    return l && l->tokens.size() > n && elastodyn::same_key(l->tokens[n].text, key);
}

bool EntryReader::skip(int n, const std::string& what) {
    c_.peek(); // section lines before the table's names are not its lines
    for (int i = 0; i < n; ++i)
        if (!c_.next(what)) return false;
    return true;
}

void EntryReader::out_channels(std::vector<std::string>& names, std::vector<int>& lines) {
    while (const aerodyn::Line* l = c_.peek()) {
        c_.next("the OUTPUT CHANNELS");
        const elastodyn::Token& first = l->tokens.front();
        if (first.text.size() >= 3 && elastodyn::same_key(first.text.substr(0, 3), "END")) return;
        if (!first.quoted) {
            names.push_back(first.text);
            lines.push_back(l->number);
            continue;
        }
        // A quoted first word holds a list of names, as GetWords splits it.
        for (const elastodyn::Token& t : elastodyn::tokenize(first.text)) {
            names.push_back(t.text);
            lines.push_back(l->number);
        }
        if (names.size() > static_cast<std::size_t>(aerodyn::max_count)) {
            diags().error(Kind::Limit, l->at(),
                          "more than " + std::to_string(aerodyn::max_count) + " output channels");
            return;
        }
    }
    diags().warning(Kind::MissingProperty, c_.here(),
                    "the OUTPUT CHANNELS end without their END line");
}

std::optional<double> EntryReader::number(const Values& v, std::size_t i, const std::string& what) {
    auto x = elastodyn::parse_number(v.tokens[i].text);
    if (!x)
        diags().error(Kind::InvalidValue, v.at(i),
                      what + ": value " + std::to_string(i + 1) + " must be a number, not '" +
                          v.tokens[i].text + "'");
    return x;
}

std::optional<int> EntryReader::integer(const Values& v, std::size_t i, const std::string& what,
                                        bool round) {
    auto x = elastodyn::parse_number(v.tokens[i].text);
    if (x && round) x = std::nearbyint(*x);
    if (!x || *x != std::floor(*x) || std::fabs(*x) > 1e9) {
        diags().error(Kind::InvalidValue, v.at(i),
                      what + ": value " + std::to_string(i + 1) + " must be an integer, not '" +
                          v.tokens[i].text + "'");
        return std::nullopt;
    }
    return static_cast<int>(*x);
}

std::optional<bool> EntryReader::logical(const Values& v, std::size_t i, const std::string& what) {
    auto b = parse_logical(v.tokens[i].text);
    if (!b)
        diags().error(Kind::InvalidValue, v.at(i),
                      what + ": value " + std::to_string(i + 1) + " must be True or False, not '" +
                          v.tokens[i].text + "'");
    return b;
}

void EntryReader::unsupported(const diag::Location& at, const std::string& what) {
    diags().warning(Kind::NotSupported, at, what + ": read, but not modelled (ignored)");
}

} // namespace yamsc::hydrodyn
