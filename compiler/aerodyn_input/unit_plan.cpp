// The blade-element plan of an FMI unit (yamsc/fmi/blade_elements.hpp): its
// text (labelled tokens; strings as LENGTH:BYTES, so any path survives; numbers
// the shortest that read back exactly) and the hook built from it.
#include "aerodyn_input/blade_elements.hpp"
#include "text/number.hpp"

#include <yamsc/fmi/blade_elements.hpp>
#include <yamsc/load_block.hpp>

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <utility>

namespace yamsc::fmi {
namespace {

constexpr const char* magic = "yamsc-blade-elements-plan";
constexpr int version = 1;

class Writer {
public:
    void label(const char* l) { out_ += std::string(out_.empty() ? "" : "\n") + l; }
    void word(const std::string& w) { out_ += ' ' + w; }
    void text(const std::string& s) { word(std::to_string(s.size()) + ':' + s); }
    void number(double v) { word(yamsc::text::shortest(v)); }
    void integer(long long v) { word(std::to_string(v)); }
    void text(const char* l, const std::string& s) {
        label(l);
        text(s);
    }
    void number(const char* l, double v) {
        label(l);
        number(v);
    }
    void integer(const char* l, long long v) {
        label(l);
        integer(v);
    }
    void integers(const char* l, const std::vector<int>& v) {
        label(l);
        integer(static_cast<long long>(v.size()));
        for (int i : v) integer(i);
    }
    void vectors(const char* l, const std::vector<Eigen::Vector3d>& v) {
        label(l);
        integer(static_cast<long long>(v.size()));
        for (const Eigen::Vector3d& x : v)
            for (int k = 0; k < 3; ++k) number(x[k]);
    }
    void points(const std::vector<runtime::BodyPoint>& points) {
        label("points");
        integer(static_cast<long long>(points.size()));
        for (const runtime::BodyPoint& p : points) {
            vectors("origin", {p.origin});
            vectors("phi", p.phi);
            vectors("psi", p.psi);
            vectors("phi1", p.phi1);
            label("orientation");
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) number(p.orientation(r, c));
        }
    }
    std::string take() { return std::move(out_) + '\n'; }

private:
    std::string out_;
};

class Reader {
public:
    explicit Reader(const std::string& s) : s_(s) {}

    void label(const char* l) {
        if (word() != l) fail(std::string("expected '") + l + "'");
    }
    std::string text() {
        skip();
        const std::size_t colon = s_.find(':', at_);
        const long long n = whole(s_.substr(at_, colon == std::string::npos ? 0 : colon - at_));
        if (colon == std::string::npos || n < 0 ||
            static_cast<unsigned long long>(n) > s_.size() - colon - 1)
            fail("a string LENGTH:BYTES");
        at_ = colon + 1 + static_cast<std::size_t>(n);
        return s_.substr(colon + 1, static_cast<std::size_t>(n));
    }
    double number() {
        const std::string w = word();
        // No ERANGE test: glibc sets it for subnormal numbers, which read back exactly.
        char* end = nullptr;
        const double v = std::strtod(w.c_str(), &end);
        if (w.empty() || *end != '\0') fail("a number, not '" + w + "'");
        return v;
    }
    long long integer() { return whole(word()); }
    std::string text(const char* l) {
        label(l);
        return text();
    }
    double number(const char* l) {
        label(l);
        return number();
    }
    long long integer(const char* l) {
        label(l);
        return integer();
    }
    std::size_t count() {
        const long long n = integer();
        // Every element takes at least two bytes of the text.
        if (n < 0 || static_cast<unsigned long long>(n) > s_.size()) fail("a count");
        return static_cast<std::size_t>(n);
    }
    std::vector<int> integers(const char* l) {
        label(l);
        std::vector<int> v(count());
        for (int& i : v) i = static_cast<int>(integer());
        return v;
    }
    std::vector<Eigen::Vector3d> vectors(const char* l) {
        label(l);
        std::vector<Eigen::Vector3d> v(count());
        for (Eigen::Vector3d& x : v)
            for (int k = 0; k < 3; ++k) x[k] = number();
        return v;
    }
    std::vector<runtime::BodyPoint> points() {
        label("points");
        std::vector<runtime::BodyPoint> points(count());
        for (runtime::BodyPoint& p : points) {
            const std::vector<Eigen::Vector3d> origin = vectors("origin");
            if (origin.size() != 1) fail("one origin");
            p.origin = origin.front();
            p.phi = vectors("phi");
            p.psi = vectors("psi");
            p.phi1 = vectors("phi1");
            label("orientation");
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) p.orientation(r, c) = number();
        }
        return points;
    }
    void end() {
        skip();
        if (at_ != s_.size()) fail("the end of the plan");
    }

private:
    void skip() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\n')) ++at_;
    }
    std::string word() {
        skip();
        const std::size_t from = at_;
        while (at_ < s_.size() && s_[at_] != ' ' && s_[at_] != '\n') ++at_;
        return s_.substr(from, at_ - from);
    }
    long long whole(const std::string& w) {
        errno = 0;
        char* end = nullptr;
        const long long v = std::strtoll(w.c_str(), &end, 10);
        if (w.empty() || *end != '\0' || errno == ERANGE || v < -1 || v > 1000000000)
            fail("an integer, not '" + w + "'");
        return v;
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw std::invalid_argument("blade-element plan, byte " + std::to_string(at_) +
                                    ": expected " + what);
    }

    const std::string& s_;
    std::size_t at_ = 0;
};

} // namespace

std::string blade_elements_plan_text(const BladeElementsPlan& plan) {
    const aero::BladeElementSetup& s = plan.setup;
    const aero::BladeElementChannels& c = s.channels;
    Writer w;
    w.label(magic);
    w.integer(version);
    w.text("aerodyn", plan.aerodyn);
    w.number("inflow_angle_tolerance", plan.inflow_angle_tolerance);
    w.text("output_prefix", s.output_prefix);
    w.integer("frozen_wake", s.frozen_wake ? 1 : 0);
    w.number("difference_step", s.difference_step);
    w.integer("wind", c.wind);
    w.integer("pitch", c.pitch);
    w.integers("hub_outputs", c.hub_outputs);
    w.label("blades");
    w.integer(static_cast<long long>(c.blades.size()));
    for (const aero::BladeElementChannels::Blade& b : c.blades) {
        w.integers("outputs", b.outputs);
        w.integers("loads", b.loads);
        w.points(b.points);
    }
    w.label("tower");
    w.integers("outputs", c.tower.outputs);
    w.integers("loads", c.tower.loads);
    w.points(c.tower.points);
    return w.take();
}

BladeElementsPlan read_blade_elements_plan(const std::string& text) {
    Reader r(text);
    BladeElementsPlan plan;
    aero::BladeElementSetup& s = plan.setup;
    aero::BladeElementChannels& c = s.channels;
    r.label(magic);
    if (r.integer() != version) throw std::invalid_argument("blade-element plan: not version 1");
    plan.aerodyn = r.text("aerodyn");
    plan.inflow_angle_tolerance = r.number("inflow_angle_tolerance");
    s.output_prefix = r.text("output_prefix");
    s.frozen_wake = r.integer("frozen_wake") != 0;
    s.difference_step = r.number("difference_step");
    c.wind = static_cast<int>(r.integer("wind"));
    c.pitch = static_cast<int>(r.integer("pitch"));
    c.hub_outputs = r.integers("hub_outputs");
    r.label("blades");
    c.blades.resize(r.count());
    for (aero::BladeElementChannels::Blade& b : c.blades) {
        b.outputs = r.integers("outputs");
        b.loads = r.integers("loads");
        b.points = r.points();
    }
    r.label("tower");
    c.tower.outputs = r.integers("outputs");
    c.tower.loads = r.integers("loads");
    c.tower.points = r.points();
    r.end();
    return plan;
}

BlockHook blade_elements_hook(std::vector<std::string> plan_texts) {
    std::vector<BladeElementsPlan> plans;
    for (const std::string& t : plan_texts) plans.push_back(read_blade_elements_plan(t));
    return [plans = std::move(plans)](const runtime::ModelView& base, const std::string& resources,
                                      const std::vector<double>&) {
        runtime::LoadBlocks blocks;
        for (const BladeElementsPlan& p : plans)
            blocks.push_back(aero::blade_element_block(aerodyn_input::with_aerodyn_rotor(
                p.setup, resources + p.aerodyn, p.inflow_angle_tolerance, std::cerr)));
        return runtime::close_blocks(base, blocks);
    };
}

} // namespace yamsc::fmi
