#pragma once
// OpenFAST's runs of floating decks as tests/data/reference/floating/cases.txt
// lists them: one line per run, the deck's .fst, OpenFAST's output (CSV, .out or
// .outb: formats/table), the platform channels compared and the kind of run.
// A held run joins with its deck, its output and one line (the folder's README).
#include "floating_support.hpp"

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace floating {

inline const std::string manifest = data_dir + "/reference/floating/cases.txt";

enum class Kind {
    decay, // a free decay from the ElastoDyn file's initial platform offsets
    waves, // a run in the SeaState file's waves (the deck must name one)
};

struct Case {
    std::string deck;                  // the .fst, resolved
    std::string output;                // OpenFAST's output, resolved
    std::vector<std::string> channels; // OpenFAST's names, without units
    Kind kind = Kind::decay;
    int line = 0; // in the manifest
    std::string name() const {
        return std::filesystem::path(deck).parent_path().filename().string() + "_" +
               std::filesystem::path(output).stem().string();
    }
};

inline Kind kind_of(const std::string& word, int line) {
    static const std::map<std::string, Kind> kinds = {{"decay", Kind::decay},
                                                      {"waves", Kind::waves}};
    const auto it = kinds.find(word);
    REQUIRE_MESSAGE(it != kinds.end(), manifest << ":" << line << ": unknown kind " << word);
    return it->second;
}

/// The manifest's runs; a line without its four fields fails the test at its line.
inline std::vector<Case> cases() {
    std::istringstream in(read(manifest));
    std::vector<Case> all;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (text.empty() || text[0] == '#') continue;
        std::istringstream fields(text);
        std::string deck, output, channels, kind, extra;
        fields >> deck >> output >> channels >> kind;
        REQUIRE_MESSAGE(!kind.empty(),
                        manifest << ":" << line << ": expected deck, output, channels, kind");
        REQUIRE_MESSAGE(!(fields >> extra), manifest << ":" << line << ": unexpected " << extra);
        Case c;
        c.deck = data_dir + "/" + deck;
        c.output = data_dir + "/" + output;
        std::istringstream names(channels);
        for (std::string name; std::getline(names, name, ',');) c.channels.push_back(name);
        c.kind = kind_of(kind, line);
        c.line = line;
        all.push_back(c);
    }
    return all;
}

} // namespace floating
