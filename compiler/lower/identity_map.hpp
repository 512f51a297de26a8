#pragma once
// A map from node addresses to value numbers for the import walk: open
// addressing in one array, so that millions of entries cost no allocation
// each. Nothing is ever iterated, so the address-dependent layout cannot
// leak into the output.
#include <cstdint>
#include <vector>

namespace yamsc::lower {

class IdentityMap {
public:
    /// The value stored for `key`, or nullptr.
    const std::uint32_t* find(const void* key) const {
        if (slots_.empty()) return nullptr;
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = hash(key) & mask; slots_[i].key != nullptr; i = (i + 1) & mask)
            if (slots_[i].key == key) return &slots_[i].value;
        return nullptr;
    }

    /// Stores `value` for `key`, which must not be present.
    void insert(const void* key, std::uint32_t value) {
        if (2 * (size_ + 1) > slots_.size()) grow();
        place(key, value);
        ++size_;
    }

    std::size_t size() const { return size_; }

private:
    struct Slot {
        const void* key = nullptr;
        std::uint32_t value = 0;
    };

    static std::size_t hash(const void* key) {
        auto x = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(key));
        x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL; // splitmix64's finaliser
        x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<std::size_t>(x ^ (x >> 31));
    }

    void place(const void* key, std::uint32_t value) {
        const std::size_t mask = slots_.size() - 1;
        std::size_t i = hash(key) & mask;
        while (slots_[i].key != nullptr) i = (i + 1) & mask;
        slots_[i] = {key, value};
    }

    void grow() {
        std::vector<Slot> old(slots_.empty() ? 1024 : 2 * slots_.size());
        old.swap(slots_);
        for (const Slot& s : old)
            if (s.key != nullptr) place(s.key, s.value);
    }

    std::vector<Slot> slots_;
    std::size_t size_ = 0;
};

} // namespace yamsc::lower
