// Every OpenFAST run of a floating deck that tests/data/reference/floating/cases.txt
// lists, run again by yamsc: `from-openfast` on its deck, `sim` with the files the
// deck names (HydroDyn, SeaState, MAP++), from the ElastoDyn file's initial
// platform offsets, over the run's time at the deck's DT; each listed platform
// channel within eps = mean|yamsc - OpenFAST| / (max - min of OpenFAST) < 2 %.
#include "floating_cases.hpp"

#include "analysis/commands.hpp"
#include "analysis/compare.hpp"

#include <iomanip>

namespace {

using namespace yamsc;

/// The reference's column for `channel` (OpenFAST's name, without the unit).
const analysis::ChannelScore* score_of(const analysis::Comparison& c, const std::string& channel) {
    for (const analysis::ChannelScore& s : c.channels)
        if (s.name == channel || s.name.rfind(channel + "_[", 0) == 0) return &s;
    return nullptr;
}

} // namespace

TEST_CASE("OpenFAST's floating runs: yamsc from each deck within 2 % on the platform DOFs") {
    const std::vector<floating::Case> runs = floating::cases();
    REQUIRE(!runs.empty());
    for (const floating::Case& run : runs) {
        CAPTURE(run.deck);
        const openfast::OpenFastDeck deck = floating::read_deck(run.deck);
        if (run.kind == floating::Kind::waves)
            REQUIRE_MESSAGE(!deck.offshore.sea_state_file.empty(),
                            floating::manifest
                                << ":" << run.line
                                << ": a run in waves needs the deck's SeaState file");
        REQUIRE_MESSAGE(deck.dt, run.deck << ": no DT");
        const analysis::Table reference = analysis::read_table(run.output);

        driver::SimOptions o;
        o.model = floating::convert(run.deck, run.name());
        const analysis::BlockOptions blocks = floating::deck_blocks(deck);
        o.hydro = blocks.hydro;
        o.sea_state = blocks.sea_state;
        o.mooring = blocks.mooring;
        o.tmax = reference.data.front().back();
        o.dt = *deck.dt;
        o.method = driver::SimMethod::rk4;
        o.channels = driver::Channels::openfast;
        o.output = floating::work_dir + "/" + run.name() + ".csv";
        std::ostringstream out, err;
        REQUIRE_MESSAGE(analysis::sim(o, out, err) == 0, err.str());

        const analysis::Comparison c =
            analysis::compare_tables(analysis::read_table(o.output), reference);
        CHECK(c.t_end == doctest::Approx(o.tmax));
        for (const std::string& channel : run.channels) {
            CAPTURE(channel);
            const analysis::ChannelScore* s = score_of(c, channel);
            REQUIRE_MESSAGE(s, run.output << " or yamsc's run has no channel " << channel);
            REQUIRE_MESSAGE(s->range > 0, channel << " does not move in " << run.output);
            MESSAGE(run.name() << " " << channel << ": eps " << std::setprecision(3)
                               << 100 * s->mean_rel_error << " %");
            CHECK(s->mean_rel_error < 0.02);
        }
    }
}
