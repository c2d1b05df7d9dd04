// An allocator for large, read-mostly arrays (BVH nodes, leaf triangles) that asks Linux for
// 2 MiB pages. A ray walking a big tree touches nodes scattered over tens of megabytes; with
// 4 KiB pages nearly every node visit is also a TLB miss. Transparent huge pages are often set
// to "madvise" (cat /sys/kernel/mm/transparent_hugepage/enabled), so they must be requested.
// Small arrays, and systems without madvise, get ordinary memory.
//
// Building is helped as much: on this project's 2-core VM the first touch of fresh memory costs
// 0.7 ms per MB on a quiet day and above 15 ms per MB under load with 4 KiB pages, against
// about 1.5 and less with 2 MiB ones (docs/performance.md, "The fast BVH's builder"). And like
// UninitialisedAllocator, resize() leaves plain numbers and structs uninitialised: the arrays
// this serves are written before they are read, and zeroing them first would touch every page
// twice (or touch pages a generous capacity never needs).
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rtlab {

template <typename T>
struct HugePageAllocator {
    using value_type = T;
    static constexpr size_t kHugePage = size_t(2) << 20;
    // Small arrays start on a cache line too: a block of mixed records (the wide BVH's nodes
    // and packets, WideBvhArrays) places 64-byte-aligned nodes at even offsets from its start.
    static constexpr std::align_val_t kSmallAlignment{alignof(T) > 64 ? alignof(T) : 64};

    HugePageAllocator() = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(size_t n) {
        size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes, kSmallAlignment));
        size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* memory = std::aligned_alloc(kHugePage, rounded);
        if (!memory) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(memory, rounded, MADV_HUGEPAGE);  // a hint: failure leaves ordinary pages
#endif
        return static_cast<T*>(memory);
    }

    void deallocate(T* p, size_t n) {
        if (n * sizeof(T) < kHugePage)
            ::operator delete(p, kSmallAlignment);
        else
            std::free(p);
    }

    template <typename U>
    void construct(U* p) {
        ::new (static_cast<void*>(p)) U;  // default-initialisation: no zeroing
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const { return true; }
};

template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace rtlab
