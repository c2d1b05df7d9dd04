// The primitives one ray has tested already. A spatial partition (grid, octree, KD-tree)
// references a primitive from every cell it overlaps, so without a mailbox a ray crossing
// several of those cells tests it again and again. Kept per query, never per primitive, so
// concurrent rays need no shared state (a per-primitive "last ray id" is not thread-safe).
#pragma once

#include <cstdint>
#include <vector>

namespace rtlab {

class Mailbox {
public:
    // True the first time prim is offered for this ray, false on every repeat.
    bool firstVisit(uint32_t prim) {
        if (slots_.empty()) slots_.assign(kInitialSlots, kEmpty);
        // Open addressing with linear probing; the table stays at most half full.
        size_t mask = slots_.size() - 1;
        for (size_t i = hash(prim) & mask;; i = (i + 1) & mask) {
            if (slots_[i] == prim) return false;
            if (slots_[i] == kEmpty) {
                slots_[i] = prim;
                if (2 * ++count_ > slots_.size()) grow();
                return true;
            }
        }
    }

private:
    static constexpr uint32_t kEmpty = 0xffffffffu;
    static constexpr size_t kInitialSlots = 64;

    static size_t hash(uint32_t prim) { return size_t(prim) * 0x9E3779B1u >> 7; }

    void grow() {
        std::vector<uint32_t> old(slots_.size() * 2, kEmpty);
        old.swap(slots_);
        size_t mask = slots_.size() - 1;
        for (uint32_t prim : old) {
            if (prim == kEmpty) continue;
            size_t i = hash(prim) & mask;
            while (slots_[i] != kEmpty) i = (i + 1) & mask;
            slots_[i] = prim;
        }
    }

    std::vector<uint32_t> slots_;
    size_t count_ = 0;
};

}  // namespace rtlab
