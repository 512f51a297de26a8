#include "analysis/batch_models.hpp"

#include "analysis/sim_case.hpp"

#include <ostream>
#include <sstream>
#include <streambuf>

namespace yamsc::analysis {

namespace {

/// The lines of rendered diagnostics that state an error (not the source
/// lines and carets), as one line.
std::string error_lines(const std::string& diagnostics) {
    std::istringstream in(diagnostics);
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.find("error: ") != std::string::npos) out += (out.empty() ? "" : " | ") + line;
    return out;
}

/// A stream buffer writing to two others.
class Tee : public std::streambuf {
public:
    Tee(std::streambuf* a, std::streambuf* b) : a_(a), b_(b) {}

protected:
    int overflow(int c) override {
        if (c == traits_type::eof()) return traits_type::not_eof(c);
        a_->sputc(static_cast<char>(c));
        b_->sputc(static_cast<char>(c));
        return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        a_->sputn(s, n);
        return b_->sputn(s, n);
    }
    int sync() override { return a_->pubsync() | b_->pubsync(); }

private:
    std::streambuf *a_, *b_;
};

} // namespace

const Loaded* BatchModels::model_of(const driver::SimOptions& sim, std::string& error) {
    const codegen::RoutineSet routines = sim_routines(sim);
    const std::string key = sim.model + "\n" + codegen::routine_names(routines);
    auto [it, fresh] = models_.try_emplace(key);
    Entry& e = it->second;
    if (fresh) {
        // Diagnostics and the compile notice on stderr as they come, and kept
        // for the summary of the rows that use the model.
        std::ostringstream diags;
        Tee tee(err_.rdbuf(), diags.rdbuf());
        std::ostream both(&tee);
        try {
            e.model = load_unbound(sim.model, "", false, both, {}, routines);
        } catch (const std::exception& ex) {
            both << "yamsc: error: " << ex.what() << "\n";
            e.model = std::nullopt;
        }
        both.flush();
        if (!e.model)
            e.error = "the model '" + sim.model + "' has errors: " + error_lines(diags.str());
    }
    if (!e.model) error = e.error;
    return e.model ? &*e.model : nullptr;
}

} // namespace yamsc::analysis
