// An allocator whose memory comes zeroed from calloc, for large buffers of numbers that start
// at zero (the renderer's images). std::vector<float>(n, 0.0f) writes every element, and on
// this machine a fresh 7 MB image so made took 2.1-2.8 ms, faulting in and clearing every page
// twice (the kernel's zeros, then the memset); from calloc the pages come zeroed by the kernel,
// faulted in only where something is written (0.5 ms with every page written).
//
// So that a vector does not write the zeros again, an element made without arguments is left
// as the memory holds it. That is zero for fresh memory only: resize() growing a vector into
// capacity it had before keeps the old values. Buffers that only ever grow from empty, as
// Image's, never see that.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace rtlab {

template <typename T>
struct ZeroedAllocator {
    static_assert(std::is_arithmetic_v<T>, "calloc's zero bytes are the value 0 of arithmetic types");
    using value_type = T;

    ZeroedAllocator() = default;
    template <typename U>
    ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        void* memory = std::calloc(n, sizeof(T));
        if (!memory) throw std::bad_alloc();
        return static_cast<T*>(memory);
    }
    void deallocate(T* p, std::size_t) noexcept { std::free(p); }

    template <typename U>
    void construct(U*) noexcept {}  // the zero calloc wrote
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <typename U>
    bool operator==(const ZeroedAllocator<U>&) const noexcept {
        return true;
    }
};

}  // namespace rtlab
