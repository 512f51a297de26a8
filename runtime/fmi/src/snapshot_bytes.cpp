// FMU states as bytes (SerializeFMUState / DeserializeFMUState): the numbers
// of a snapshot in this machine's byte order, for the same unit on the same
// platform (the standard asks no more), behind a tag and the sizes they were
// written with, which reading checks.
#include "instance.hpp"

#include <cstring>

namespace yamsc::fmi {
namespace {

constexpr char tag[8] = {'y', 'a', 'm', 's', 'c', 'F', 'S', '1'};

class Writer {
public:
    template <class T> void put(const T& v) {
        const auto* p = reinterpret_cast<const unsigned char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof v);
    }
    void put(const std::vector<double>& v) {
        put(static_cast<std::uint64_t>(v.size()));
        for (double d : v) put(d);
    }
    std::vector<unsigned char> bytes;
};

class Reader {
public:
    Reader(const unsigned char* bytes, std::size_t size) : p_(bytes), end_(bytes + size) {}
    template <class T> bool get(T& v) {
        if (static_cast<std::size_t>(end_ - p_) < sizeof v) return false;
        std::memcpy(&v, p_, sizeof v);
        p_ += sizeof v;
        return true;
    }
    bool get(std::vector<double>& v) {
        std::uint64_t n = 0;
        if (!get(n) || n > static_cast<std::uint64_t>(end_ - p_) / sizeof(double)) return false;
        v.resize(static_cast<std::size_t>(n));
        for (double& d : v)
            if (!get(d)) return false;
        return true;
    }
    bool at_end() const { return p_ == end_; }

private:
    const unsigned char* p_;
    const unsigned char* end_;
};

} // namespace

std::optional<std::vector<unsigned char>> serialize(const Snapshot& s, std::string& error) {
    if (s.abm4 && s.abm4->history() > 0) {
        error = "ABM4's history of derivatives is not serialized; serialize a state of an RK4 or "
                "CVODE run, or one taken before the first ABM4 step";
        return std::nullopt;
    }
    const Numbers& n = s.numbers;
    Writer w;
    for (char c : tag) w.put(c);
    w.put(static_cast<std::int32_t>(s.interface));
    w.put(static_cast<std::int32_t>(n.mode));
    w.put(method_code(n.method));
    w.put(n.t);
    w.put(n.step);
    w.put(static_cast<std::uint8_t>(n.tolerance.has_value()));
    w.put(n.tolerance.value_or(0.0));
    w.put(n.t_accepted);
    for (const std::vector<double>* v : {&n.x, &n.u, &n.p, &n.x_accepted, &n.u_accepted}) w.put(*v);
    return std::move(w.bytes);
}

Snapshot* deserialize(const unsigned char* bytes, std::size_t size, std::string& error) {
    Reader r(bytes, size);
    char read_tag[8] = {};
    for (char& c : read_tag)
        if (!r.get(c)) break;
    if (std::memcmp(read_tag, tag, sizeof tag) != 0) {
        error = "the bytes are not an FMU state of a yamsc unit";
        return nullptr;
    }
    auto s = std::make_unique<Snapshot>();
    Numbers& n = s->numbers;
    std::int32_t interface = 0, mode = 0, method = 0;
    std::uint8_t has_tolerance = 0;
    double tolerance = 0.0;
    bool ok = r.get(interface) && r.get(mode) && r.get(method) && r.get(n.t) && r.get(n.step) &&
              r.get(has_tolerance) && r.get(tolerance) && r.get(n.t_accepted);
    for (std::vector<double>* v : {&n.x, &n.u, &n.p, &n.x_accepted, &n.u_accepted})
        ok = ok && r.get(*v);
    const auto m = method_of_code(method);
    if (!ok || !r.at_end() || !m || interface < 0 || interface > 1 || mode < 0 ||
        mode > static_cast<std::int32_t>(Mode::terminated)) {
        error = "the FMU state's bytes are cut short or damaged";
        return nullptr;
    }
    s->interface = static_cast<Interface>(interface);
    n.mode = static_cast<Mode>(mode);
    n.method = *m;
    if (has_tolerance) n.tolerance = tolerance;
    return s.release();
}

Status Instance::serialized_size(const Snapshot* state, std::size_t* size) const {
    if (!state || !size) return fail("SerializedFMUStateSize: no state given");
    std::string error;
    const auto bytes = serialize(*state, error);
    if (!bytes) return fail("SerializedFMUStateSize: " + error);
    *size = bytes->size();
    return Status::ok;
}

Status Instance::serialize_state(const Snapshot* state, unsigned char* bytes,
                                 std::size_t size) const {
    if (!state || !bytes) return fail("SerializeFMUState: no state given");
    std::string error;
    const auto out = serialize(*state, error);
    if (!out) return fail("SerializeFMUState: " + error);
    if (out->size() != size)
        return fail("SerializeFMUState: the state takes " + std::to_string(out->size()) +
                    " bytes, not " + std::to_string(size));
    std::memcpy(bytes, out->data(), size);
    return Status::ok;
}

Status Instance::deserialize_state(const unsigned char* bytes, std::size_t size,
                                   Snapshot** state) const {
    if (!bytes || !state) return fail("DeserializeFMUState: no bytes given");
    std::string error;
    Snapshot* s = deserialize(bytes, size, error);
    if (!s) return fail("DeserializeFMUState: " + error);
    // Sizes are checked by SetFMUState against the model it is set into.
    s->owner = this;
    if (*state) free_state(*state);
    *state = s;
    return Status::ok;
}

} // namespace yamsc::fmi
