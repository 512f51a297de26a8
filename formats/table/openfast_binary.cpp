// Reading OpenFAST's binary output files (openfast_binary.hpp).
#include "table/openfast_binary.hpp"

#include "diag/errors.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

namespace yamsc::table {

namespace {

enum class FormatId : std::int16_t {
    with_time = 1,
    without_time = 2,
    uncompressed = 3,
    name_length_in_header = 4,
};

/// A cursor over the file's bytes that names the offset of what it fails to read.
class Reader {
public:
    Reader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        throw diag::UserError(name_ + ": byte " + std::to_string(at) + ": " + message);
    }
    std::size_t offset() const { return pos_; }

    template <class T> T value(const char* what) {
        if (bytes_.size() - pos_ < sizeof(T))
            fail(pos_, std::string("the file ends in the ") + what);
        T v;
        std::memcpy(&v, bytes_.data() + pos_, sizeof(T)); // the file is little-endian, as x86
        pos_ += sizeof(T);
        return v;
    }

    /// `count` items of `size` bytes each must follow.
    void need(std::uint64_t count, std::size_t size, const char* what) const {
        if (count > (bytes_.size() - pos_) / size)
            fail(pos_, std::string("the file ends in the ") + what + " (" + std::to_string(count) +
                           " expected)");
    }

    std::string text(std::size_t length, const char* what) {
        need(length, 1, what);
        std::string s = bytes_.substr(pos_, length);
        pos_ += length;
        const auto b = s.find_first_not_of(' ');
        const auto e = s.find_last_not_of(' ');
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    }

private:
    const std::string& bytes_;
    const std::string& name_;
    std::size_t pos_ = 0;
};

std::string column_name(const std::string& name, std::string unit) {
    // Units are written in parentheses: "(kN-m)".
    if (unit.size() >= 2 && unit.front() == '(' && unit.back() == ')')
        unit = unit.substr(1, unit.size() - 2);
    return name + "_[" + unit + "]";
}

} // namespace

Table parse_openfast_binary(const std::string& bytes, const std::string& name) {
    Reader in(bytes, name);
    const auto id = static_cast<FormatId>(in.value<std::int16_t>("format id"));
    if (id != FormatId::with_time && id != FormatId::without_time && id != FormatId::uncompressed &&
        id != FormatId::name_length_in_header)
        in.fail(0, "format id " + std::to_string(static_cast<int>(id)) +
                       " is not one of OpenFAST's (1, 2, 3 or 4): not an OpenFAST binary file");
    std::size_t name_length = 10;
    if (id == FormatId::name_length_in_header) {
        const std::size_t at = in.offset();
        const auto n = in.value<std::int16_t>("length of channel names");
        if (n < 1) in.fail(at, "the length of channel names is " + std::to_string(n));
        name_length = static_cast<std::size_t>(n);
    }
    std::size_t at = in.offset();
    const auto channels = in.value<std::int32_t>("number of channels");
    if (channels < 1) in.fail(at, "the number of channels is " + std::to_string(channels));
    at = in.offset();
    const auto steps = in.value<std::int32_t>("number of time steps");
    if (steps < 1) in.fail(at, "the number of time steps is " + std::to_string(steps));
    const auto nc = static_cast<std::size_t>(channels);
    const auto nt = static_cast<std::size_t>(steps);

    double time_a = 0, time_b = 0; // slope and offset (1), or first time and step
    const std::size_t time_at = in.offset();
    time_a = in.value<double>("time scaling");
    time_b = in.value<double>("time scaling");
    if (!std::isfinite(time_a) || !std::isfinite(time_b) ||
        (id == FormatId::with_time && time_a == 0))
        in.fail(time_at, "the time scaling is not usable (" + std::to_string(time_a) + ", " +
                             std::to_string(time_b) + ")");

    // What the channel count announces must be there before anything is allocated for it.
    const std::uint64_t scaling_bytes =
        id == FormatId::uncompressed ? 0 : 8 * static_cast<std::uint64_t>(nc);
    in.need(scaling_bytes + 2 * static_cast<std::uint64_t>(nc + 1) * name_length, 1,
            "channel scaling, names and units");
    std::vector<float> slope(nc, 1.0f), offset(nc, 0.0f);
    const std::size_t scaling_at = in.offset();
    if (id != FormatId::uncompressed) {
        in.need(2 * static_cast<std::uint64_t>(nc), sizeof(float), "channel scaling");
        for (float& s : slope) s = in.value<float>("channel scaling");
        for (float& o : offset) o = in.value<float>("channel scaling");
    }
    at = in.offset();
    const auto description_length = in.value<std::int32_t>("description length");
    if (description_length < 0)
        in.fail(at, "the description length is " + std::to_string(description_length));
    in.text(static_cast<std::size_t>(description_length), "description");

    in.need(2 * static_cast<std::uint64_t>(nc + 1), name_length, "channel names and units");
    std::vector<std::string> names(nc + 1), units(nc + 1);
    for (std::string& n : names) n = in.text(name_length, "channel names");
    for (std::string& u : units) u = in.text(name_length, "channel units");

    // The whole size is checked before anything is allocated for the samples.
    const std::size_t value_size =
        id == FormatId::uncompressed ? sizeof(double) : sizeof(std::int16_t);
    const std::uint64_t time_bytes =
        id == FormatId::with_time ? 4 * static_cast<std::uint64_t>(nt) : 0;
    in.need(time_bytes + static_cast<std::uint64_t>(nt) * nc * value_size, 1,
            id == FormatId::with_time ? "packed times and channel data" : "channel data");

    Table t;
    for (std::size_t j = 0; j <= nc; ++j) t.columns.push_back(column_name(names[j], units[j]));
    t.data.assign(nc + 1, std::vector<double>(nt));

    std::vector<double>& time = t.data[0];
    const std::size_t packed_times_at = in.offset();
    if (id == FormatId::with_time) {
        for (std::size_t i = 0; i < nt; ++i)
            time[i] =
                (static_cast<double>(in.value<std::int32_t>("packed times")) - time_b) / time_a;
    } else {
        for (std::size_t i = 0; i < nt; ++i) time[i] = time_a + time_b * static_cast<double>(i);
    }
    for (std::size_t i = 0; i < nt; ++i)
        if (!std::isfinite(time[i]))
            in.fail(id == FormatId::with_time ? packed_times_at + 4 * i : time_at,
                    "the time of step " + std::to_string(i + 1) + " is not a finite number");
    for (std::size_t i = 1; i < nt; ++i)
        if (!(time[i] > time[i - 1]))
            in.fail(id == FormatId::with_time ? packed_times_at + 4 * i : time_at,
                    "time does not rise at step " + std::to_string(i + 1));

    for (std::size_t j = 0; j < nc; ++j)
        if (id != FormatId::uncompressed &&
            (!std::isfinite(slope[j]) || !std::isfinite(offset[j]) || slope[j] == 0.0f))
            in.fail(scaling_at + 4 * j, "channel " + names[j + 1] + ": its scaling is not usable");
    for (std::size_t i = 0; i < nt; ++i)
        for (std::size_t j = 0; j < nc; ++j) {
            const std::size_t value_at = in.offset();
            double v;
            if (id == FormatId::uncompressed) {
                v = in.value<double>("channel data");
            } else {
                const double packed = in.value<std::int16_t>("channel data");
                v = (packed - static_cast<double>(offset[j])) / static_cast<double>(slope[j]);
            }
            if (!std::isfinite(v))
                in.fail(value_at, "channel " + names[j + 1] + " at step " + std::to_string(i + 1) +
                                      ": not a finite number");
            t.data[j + 1][i] = v;
        }
    // Bytes after the announced steps are ignored, as OpenFAST's ReadFASTbin and
    // openfast_toolbox ignore them (openfast_toolbox's own example file has some).
    return t;
}

Table read_openfast_binary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw diag::UserError("cannot read '" + path + "'");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw diag::UserError("cannot read '" + path + "'");
    return parse_openfast_binary(bytes, path);
}

} // namespace yamsc::table
