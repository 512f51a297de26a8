#include "openfast/gauge_nodes.hpp"

#include "elastodyn/file.hpp"

#include <cctype>
#include <cstdlib>
#include <string>

namespace yamsc::openfast {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// The whole numbers before `key` on its line: "10, 19, 28   TwrGagNd  - ...".
std::vector<int> values_before(const diag::SourceFile& f, const std::string& key) {
    for (int line = 3; line <= f.line_count(); ++line) {
        const std::vector<elastodyn::Token> t = elastodyn::tokenize(f.line(line));
        std::vector<int> values;
        for (const elastodyn::Token& token : t) {
            if (lower(token.text) == lower(key)) return values;
            char* end = nullptr;
            const long v = std::strtol(token.text.c_str(), &end, 10);
            if (token.text.empty() || *end != '\0') break;
            values.push_back(static_cast<int>(v));
        }
    }
    return {};
}

std::vector<int> gauges(const diag::SourceFile& f, const std::string& count_key,
                        const std::string& list_key) {
    const std::vector<int> count = values_before(f, count_key);
    if (count.empty() || count.front() <= 0) return {};
    std::vector<int> nodes = values_before(f, list_key);
    if (nodes.size() > static_cast<std::size_t>(count.front()))
        nodes.resize(static_cast<std::size_t>(count.front()));
    return nodes;
}

} // namespace

GaugeNodes read_gauge_nodes(const diag::SourceFile& elastodyn) {
    return {gauges(elastodyn, "NTwGages", "TwrGagNd"), gauges(elastodyn, "NBlGages", "BldGagNd")};
}

} // namespace yamsc::openfast
