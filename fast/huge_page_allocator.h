// An allocator for large, read-mostly arrays (BVH nodes, leaf triangles) that asks Linux for
// 2 MiB pages. A ray walking a big tree touches nodes scattered over tens of megabytes; with
// 4 KiB pages nearly every node visit is also a TLB miss. Transparent huge pages are often set
// to "madvise" (cat /sys/kernel/mm/transparent_hugepage/enabled), so they must be requested.
// Small arrays, and systems without madvise, get ordinary memory.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rtlab {

template <typename T>
struct HugePageAllocator {
    using value_type = T;
    static constexpr size_t kHugePage = size_t(2) << 20;

    HugePageAllocator() = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(size_t n) {
        size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
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
            ::operator delete(p, std::align_val_t(alignof(T)));
        else
            std::free(p);
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const { return true; }
};

}  // namespace rtlab
