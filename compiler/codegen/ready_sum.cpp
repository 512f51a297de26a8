#include "codegen/ready_sum.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <tuple>

namespace yamsc::codegen {

Timed product(const Timed& a, const Timed& b) {
    return {a.text + " * " + b.text, std::max(a.ready, b.ready) + mul_latency, false};
}

namespace {

struct Operand {
    Timed value;
    int position = 0;
    bool positive = false; // holds the first term; every other operand is subtracted
};

std::string right_operand(const Timed& t) {
    return t.sum ? "(" + t.text + ")" : t.text;
}

} // namespace

Timed difference(const Timed& first, const std::vector<Timed>& terms) {
    std::vector<Operand> open;
    int position = 0;
    if (!first.text.empty()) open.push_back({first, position++, true});
    for (const Timed& t : terms) open.push_back({t, position++, false});
    if (open.empty()) throw diag::InternalError("code generation: an empty difference");
    auto earlier = [](const Operand& a, const Operand& b) {
        return std::tie(a.value.ready, a.position) < std::tie(b.value.ready, b.position);
    };
    while (open.size() > 1) {
        std::sort(open.begin(), open.end(), earlier);
        Operand a = std::move(open[0]), b = std::move(open[1]);
        open.erase(open.begin(), open.begin() + 2);
        // The first term stays on the left of its `-`; of two terms a sum goes
        // left, where it needs no parentheses (a + b is b + a, exactly).
        if (b.positive || (!a.positive && b.value.sum && !a.value.sum)) std::swap(a, b);
        const int ready = std::max(a.value.ready, b.value.ready) + add_latency;
        const std::string text =
            a.value.text + (a.positive ? " - " : " + ") + right_operand(b.value);
        open.push_back({{text, ready, true}, position++, a.positive});
    }
    Operand& root = open.front();
    if (root.positive) return root.value;
    return {"-" + right_operand(root.value), root.value.ready, false};
}

} // namespace yamsc::codegen
