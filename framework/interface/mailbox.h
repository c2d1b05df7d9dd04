// The primitives one ray has tested already. A spatial partition (grid, octree, KD-tree)
// references a primitive from every cell it overlaps, so without a mailbox a ray crossing
// several of those cells tests it again and again. Kept per query, never per primitive, so
// concurrent rays need no shared state (a per-primitive "last ray id" is not thread-safe).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

class Mailbox {
public:
    // True the first time prim is offered for this ray, false on every repeat.
    bool firstVisit(uint32_t prim) {
        // Most rays test a few dozen primitives: a linear scan of an array on the stack beats
        // any table, and costs no allocation. Past that, a hash set on the heap.
        if (table_.empty()) {
            for (uint32_t i = 0; i < count_; ++i)
                if (recent_[i] == prim) return false;
            if (count_ < recent_.size()) {
                recent_[count_++] = prim;
                return true;
            }
            table_.assign(4 * recent_.size(), kEmpty);
            for (uint32_t p : recent_) insert(p);
        }
        return insert(prim);
    }

private:
    static constexpr uint32_t kEmpty = 0xffffffffu;

    static size_t hash(uint32_t prim) { return size_t(prim) * 0x9E3779B1u >> 7; }

    // Open addressing with linear probing; the table stays at most half full.
    bool insert(uint32_t prim) {
        size_t mask = table_.size() - 1;
        for (size_t i = hash(prim) & mask;; i = (i + 1) & mask) {
            if (table_[i] == prim) return false;
            if (table_[i] == kEmpty) {
                table_[i] = prim;
                if (2 * ++stored_ > table_.size()) grow();
                return true;
            }
        }
    }

    void grow() {
        std::vector<uint32_t> old(table_.size() * 2, kEmpty);
        old.swap(table_);
        stored_ = 0;
        for (uint32_t prim : old)
            if (prim != kEmpty) insert(prim);
    }

    std::array<uint32_t, 32> recent_;
    uint32_t count_ = 0;
    std::vector<uint32_t> table_;
    size_t stored_ = 0;
};

}  // namespace rtlab
