#pragma once
// Helpers shared by the SID tests: read a text, list diagnostics compactly, build a synthetic
// SID with non-trivial numbers.
#include "sid/reader.hpp"
#include "sid/writer.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>

namespace yamsc::test {

struct ReadResult {
    std::optional<sid::Sid> sid;
    diag::Diagnostics diags;
};

inline ReadResult read_text(std::string text, std::string path = "test.sid") {
    ReadResult r;
    r.sid = sid::read_sid(
        std::make_shared<const diag::SourceFile>(std::move(path), std::move(text)), r.diags);
    return r;
}

inline std::string data_path(const std::string& name) {
    return std::string(YAMSC_SOURCE_DIR) + "/tests/sid/data/" + name;
}

inline std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// "L:C: severity: message [kind]" per diagnostic, one per line.
inline std::string brief(const diag::Diagnostics& diags) {
    std::string out;
    for (const diag::Diagnostic& d : diags.all()) {
        const char* severity = d.severity == diag::Severity::error     ? "error"
                               : d.severity == diag::Severity::warning ? "warning"
                                                                       : "note";
        out += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + severity +
               ": " + d.message + " [" + std::string(diag::kind_name(d.kind)) + "]\n";
    }
    return out;
}

/// Numbers that exercise the writer: many magnitudes and signs, values like 1/3 that have no
/// short decimal form, and exact zeros.
class NumberStream {
public:
    double next() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        const double unit = static_cast<double>(state_ >> 11) / 9007199254740992.0; // [0, 1)
        const int kind = static_cast<int>((state_ >> 3) % 8);
        switch (kind) {
        case 0:
            return 0.0;
        case 1:
            return 1.0 / (3.0 + unit);
        case 2:
            return -unit * 1e-300;
        case 3:
            return unit * 2.5e17;
        default:
            return (unit - 0.5) * std::pow(10.0, kind - 5);
        }
    }

private:
    std::uint64_t state_ = 0x9E3779B97F4A7C15ULL;
};

inline sid::Taylor filled(int order, int nrow, int ncol, int nq, int structure,
                          NumberStream& numbers) {
    sid::Taylor t = sid::Taylor::zeros(order, nrow, ncol, nq, structure);
    for (double& v : t.m0) v = numbers.next();
    for (double& v : t.m1) v = numbers.next();
    if (structure == 2) { // make it symmetric: the lower triangle wins
        for (int i = 0; i < nrow; ++i) {
            for (int j = i + 1; j < ncol; ++j) {
                t.at0(i, j) = t.at0(j, i);
                for (int k = 0; order == 1 && k < nq; ++k) t.at1(i, j, k) = t.at1(j, i, k);
            }
        }
    }
    return t;
}

/// A body with 2 modes and 3 nodes; most blocks have first-order terms.
inline sid::Sid synthetic_sid() {
    NumberStream numbers;
    const int nq = 2;
    sid::Sid s;
    s.mass = 1234.5678901234567;
    s.nq = nq;
    s.mode_names = {"Eigen Mode    1", "fore-aft #2 (0.32 Hz)"};
    for (int n = 0; n < 3; ++n) {
        sid::Node node;
        node.id = n + 1;
        node.rframe = n == 2 ? "tip frame" : "body ref";
        node.origin = filled(1, 3, 1, nq, 3, numbers);
        node.phi = filled(1, 3, nq, nq, 3, numbers);
        node.psi = filled(0, 3, nq, nq, 3, numbers);
        node.ap = filled(1, 3, 3, nq, 3, numbers);
        if (n == 2) {
            node.has_sigma = true;
            node.sigma = filled(1, 6, 1, nq, 3, numbers);
        }
        s.nodes.push_back(node);
    }
    s.md_cm = filled(1, 3, 1, nq, 3, numbers);
    s.J = filled(1, 3, 3, nq, 2, numbers);
    s.Ct = filled(1, nq, 3, nq, 3, numbers);
    s.Cr = filled(1, nq, 3, nq, 3, numbers);
    s.Me = filled(0, nq, nq, nq, 2, numbers);
    s.Gr = filled(1, 3, 3 * nq, nq, 3, numbers);
    s.Ge = filled(0, nq, 3 * nq, 0, 3, numbers); // nq = 0 in an order-0 block, as welib writes
    s.Oe = filled(1, nq, 6, nq, 3, numbers);
    s.ksigma = sid::Taylor::zeros(0, nq, 1, nq, 0);
    s.Ke = filled(0, nq, nq, nq, 2, numbers);
    s.De = sid::Taylor::zeros(0, nq, nq, nq, 1);
    s.De.at0(0, 0) = 0.05;
    s.De.at0(1, 1) = 1.0 / 7.0;
    return s;
}

} // namespace yamsc::test
