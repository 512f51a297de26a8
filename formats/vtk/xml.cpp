#include "vtk/xml.hpp"

#include "diag/errors.hpp"

namespace yamsc::vtk::xml {

const std::string* Element::attribute(const std::string& key) const {
    for (const auto& [k, v] : attributes)
        if (k == key) return &v;
    return nullptr;
}

std::string where(const std::string& text, const std::string& name, std::size_t offset) {
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return name + ":" + std::to_string(line) + ":" + std::to_string(col);
}

namespace {

class Parser {
public:
    Parser(const std::string& text, const std::string& name, std::size_t max_depth)
        : s_(text), name_(name), max_depth_(max_depth) {}

    Element document() {
        skip_misc();
        if (at("<?xml")) {
            const std::size_t end = s_.find("?>", i_);
            if (end == std::string::npos) fail(i_, "an XML declaration without its end '?>'");
            i_ = end + 2;
        }
        skip_misc();
        if (i_ >= s_.size() || s_[i_] != '<') fail(i_, "expected an element");
        Element root = element(1);
        skip_misc();
        if (i_ < s_.size()) fail(i_, "text after the root element");
        return root;
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        throw diag::UserError(where(s_, name_, at) + ": " + message);
    }
    bool at(const char* word) const {
        return s_.compare(i_, std::char_traits<char>::length(word), word) == 0;
    }
    static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    static bool name_char(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-' || c == ':' || c == '.';
    }
    void skip_space() {
        while (i_ < s_.size() && space(s_[i_])) ++i_;
    }
    void skip_comment() {
        const std::size_t end = s_.find("-->", i_ + 4);
        if (end == std::string::npos) fail(i_, "a comment without its end '-->'");
        i_ = end + 3;
    }
    void skip_misc() {
        for (;;) {
            skip_space();
            if (at("<!--"))
                skip_comment();
            else
                return;
        }
    }
    std::string name() {
        const std::size_t start = i_;
        while (i_ < s_.size() && name_char(s_[i_])) ++i_;
        if (i_ == start) fail(start, "expected a name");
        return s_.substr(start, i_ - start);
    }
    std::string decoded(std::size_t start, std::size_t end) const {
        std::string out;
        for (std::size_t k = start; k < end; ++k) {
            if (s_[k] != '&') {
                out += s_[k];
                continue;
            }
            static const std::pair<const char*, char> entities[] = {
                {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
            bool known = false;
            for (const auto& [e, c] : entities) {
                const std::size_t n = std::char_traits<char>::length(e);
                if (s_.compare(k, n, e) == 0) {
                    out += c;
                    k += n - 1;
                    known = true;
                    break;
                }
            }
            if (!known) fail(k, "an entity other than XML's five (&amp; &lt; &gt; &quot; &apos;)");
        }
        return out;
    }
    Element element(std::size_t depth) {
        if (depth > max_depth_)
            fail(i_, "elements nested deeper than " + std::to_string(max_depth_));
        Element e;
        e.offset = i_;
        ++i_; // '<'
        e.name = name();
        for (;;) {
            skip_space();
            if (i_ >= s_.size()) fail(e.offset, "element '" + e.name + "' without its end");
            if (at("/>")) {
                i_ += 2;
                return e;
            }
            if (s_[i_] == '>') {
                ++i_;
                break;
            }
            const std::size_t key_at = i_;
            std::string key = name();
            skip_space();
            if (i_ >= s_.size() || s_[i_] != '=') fail(i_, "expected '=' after '" + key + "'");
            ++i_;
            skip_space();
            if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\''))
                fail(i_, "expected a quoted value of '" + key + "'");
            const char quote = s_[i_++];
            const std::size_t end = s_.find(quote, i_);
            if (end == std::string::npos) fail(i_ - 1, "a value without its closing quote");
            if (e.attribute(key)) fail(key_at, "attribute '" + key + "' given twice");
            e.attributes.emplace_back(std::move(key), decoded(i_, end));
            i_ = end + 1;
        }
        e.text_offset = i_;
        for (;;) {
            const std::size_t lt = s_.find('<', i_);
            if (lt == std::string::npos) fail(e.offset, "element '" + e.name + "' without its end");
            if (e.text.empty()) e.text_offset = i_;
            e.text += decoded(i_, lt);
            i_ = lt;
            if (at("<!--")) {
                skip_comment();
            } else if (at("</")) {
                const std::size_t close = i_;
                i_ += 2;
                if (name() != e.name) fail(close, "'</...>' does not close '" + e.name + "'");
                skip_space();
                if (i_ >= s_.size() || s_[i_] != '>') fail(i_, "expected '>'");
                ++i_;
                return e;
            } else if (at("<?") || at("<!")) {
                fail(i_, "a processing instruction, DOCTYPE or CDATA (not in VTK's files)");
            } else {
                e.children.push_back(element(depth + 1));
            }
        }
    }

    const std::string& s_;
    const std::string& name_;
    std::size_t max_depth_;
    std::size_t i_ = 0;
};

} // namespace

Element parse(const std::string& text, const std::string& name, std::size_t max_depth) {
    return Parser(text, name, max_depth).document();
}

} // namespace yamsc::vtk::xml
