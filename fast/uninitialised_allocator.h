// An allocator for arrays whose every element is written before it is read: resize() leaves
// plain numbers and structs uninitialised instead of zeroing them, which spares a pass over
// fresh memory (tens of megabytes for a big grid's references).
//
// Ordinary pages, not HugePageAllocator's: measured on this project's 2-core VM, arrays
// allocated and freed build after build on 2 MiB pages grew slower from one build to the next
// (a 1M-triangle grid fill went from 54 to 190 ms), while 4 KiB pages stayed at 57-73 ms.
#pragma once

#include <memory>
#include <utility>

namespace rtlab {

template <typename T>
struct UninitialisedAllocator : std::allocator<T> {
    using value_type = T;
    template <typename U>
    struct rebind {
        using other = UninitialisedAllocator<U>;
    };

    UninitialisedAllocator() = default;
    template <typename U>
    UninitialisedAllocator(const UninitialisedAllocator<U>&) {}

    template <typename U>
    void construct(U* p) {
        ::new (static_cast<void*>(p)) U;  // default-initialisation: no zeroing
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace rtlab
