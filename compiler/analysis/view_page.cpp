#include "analysis/view_page.hpp"

#include "analysis/svg_plot.hpp"
#include "diag/errors.hpp"
#include "driver/json.hpp"
#include "yamsc_viewer/page.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace yamsc::analysis {

namespace {

// The page decodes arrays as little-endian typed arrays (viewer/src/data.js),
// so each value is written byte by byte whatever this machine's order.
bool little_endian() {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

template <class T> std::string array_base64(const std::vector<T>& values) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>);
    static const bool little = little_endian();
    std::string bytes(values.size() * sizeof(T), '\0');
    for (std::size_t i = 0; i < values.size(); ++i) {
        unsigned char raw[sizeof(T)];
        std::memcpy(raw, &values[i], sizeof(T));
        for (std::size_t b = 0; b < sizeof(T); ++b)
            bytes[i * sizeof(T) + b] = static_cast<char>(little ? raw[b] : raw[sizeof(T) - 1 - b]);
    }
    return '"' + base64(bytes.data(), bytes.size()) + '"';
}

// A JSON string that is also safe inside <script>: `<`, `>` and `&` escaped, so
// no name can close the element (in JSON they only ever stand for themselves).
std::string json_string(const std::string& s) {
    std::string out;
    for (const char c : driver::json::quote(s)) {
        if (c == '<')
            out += "\\u003c";
        else if (c == '>')
            out += "\\u003e";
        else if (c == '&')
            out += "\\u0026";
        else
            out += c;
    }
    return out;
}

void replace_all(std::string& text, const std::string& key, const std::string& value) {
    for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
        text.replace(at, key.size(), value);
}

} // namespace

std::string base64(const void* data, std::size_t size) {
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* p = static_cast<const unsigned char*>(data);
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < size; i += 3) {
        const unsigned v = (p[i] << 16) | (p[i + 1] << 8) | p[i + 2];
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += alphabet[(v >> 6) & 63];
        out += alphabet[v & 63];
    }
    if (i < size) {
        const unsigned v = (p[i] << 16) | (i + 1 < size ? p[i + 1] << 8 : 0);
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += i + 1 < size ? alphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

bool view_page_available() {
    return !viewer::page_script().empty();
}

std::string view_page_data(const ViewPage& page) {
    const ViewScene& s = page.scene;
    if (s.positions.size() != s.times.size() * s.point_count * 3)
        throw std::invalid_argument("view page: positions are not frames x points x 3");
    std::string out = "{\"format\":\"yamsc-view 1\",\"title\":" + json_string(page.title);
    out += ",\"parts\":[";
    for (std::size_t i = 0; i < s.part_names.size(); ++i)
        out += (i ? "," : "") + json_string(s.part_names[i]);
    out += "],\"points\":" + std::to_string(s.point_count);
    out += ",\"times\":" + array_base64(s.times);
    out += ",\"positions\":" + array_base64(s.positions);
    out += ",\"cells\":{\"type\":" + array_base64(s.cell_type);
    out += ",\"offsets\":" + array_base64(s.offsets);
    out += ",\"connectivity\":" + array_base64(s.connectivity);
    out += ",\"part\":" + array_base64(s.part);
    out += ",\"kind\":" + array_base64(s.kind) + "}";
    out += ",\"channels\":{\"times\":" + array_base64(page.channel_times) + ",\"series\":[";
    for (std::size_t i = 0; i < page.channels.size(); ++i) {
        const ViewChannel& c = page.channels[i];
        if (c.values.size() != page.channel_times.size())
            throw std::invalid_argument("view page: channel " + c.name +
                                        " has not one value a row");
        out += std::string(i ? "," : "") + "{\"name\":" + json_string(c.name) +
               ",\"unit\":" + json_string(c.unit) + ",\"values\":" + array_base64(c.values) + "}";
    }
    return out + "]}}";
}

std::string view_page_html(const ViewPage& page) {
    if (!view_page_available())
        throw diag::UserError("this yamsc was built without the page of yamsc view (node and npm "
                              "were not found at build time; scripts/install-deps.sh installs "
                              "them, then rebuild)");
    std::string html(viewer::page_template());
    replace_all(html, "@TITLE@", xml_escape(page.title));
    // The data and the script last: their text is not searched for placeholders.
    const auto data_at = html.find("@DATA@");
    const auto script_at = html.find("@SCRIPT@");
    if (data_at == std::string::npos || script_at == std::string::npos || script_at < data_at)
        throw std::logic_error("the page template lacks @DATA@ before @SCRIPT@");
    const std::string script(viewer::page_script());
    return html.substr(0, data_at) + view_page_data(page) +
           html.substr(data_at + 6, script_at - data_at - 6) + script + html.substr(script_at + 8);
}

} // namespace yamsc::analysis
