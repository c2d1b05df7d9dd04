// The numbers of a viewer page, as one block of named typed arrays that the page reads with
// DataView and typed arrays: parsed, never evaluated (viewer/page/viewer.js, readBlob).
//
// Layout, little-endian: u32 magic "RTvw", u32 section count, then per section
//   u8 name length, name (ASCII letters, digits, '.', '_'), u8 element type, padding to 4,
//   u32 element count, the elements, padding to 4.
// The page gets it deflated (zlib) and in base64, inside a <script type="application/octet-stream">
// element, which no browser runs.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace rtlab::viewer {

enum class ElementType : uint8_t { U8 = 1, U16 = 2, U32 = 3, I32 = 4, F32 = 5, F64 = 6 };

template <typename T>
constexpr ElementType elementTypeOf() {
    if constexpr (std::is_same_v<T, uint8_t>) return ElementType::U8;
    else if constexpr (std::is_same_v<T, uint16_t>) return ElementType::U16;
    else if constexpr (std::is_same_v<T, uint32_t>) return ElementType::U32;
    else if constexpr (std::is_same_v<T, int32_t>) return ElementType::I32;
    else if constexpr (std::is_same_v<T, float>) return ElementType::F32;
    else {
        static_assert(std::is_same_v<T, double>, "a section holds plain numbers");
        return ElementType::F64;
    }
}

class ViewerBlob {
public:
    ViewerBlob();

    template <typename T>
    void add(const std::string& name, std::span<const T> values) {
        addRaw(name, elementTypeOf<T>(), values.size(), values.data(), values.size_bytes());
    }
    template <typename T>
    void add(const std::string& name, const std::vector<T>& values) {
        add(name, std::span<const T>(values));
    }

    size_t sections() const { return sections_; }
    const std::vector<uint8_t>& bytes() const { return bytes_; }
    // The block deflated (zlib, level 1) and in base64, as the page reads it.
    std::string deflatedBase64() const;

private:
    void addRaw(const std::string& name, ElementType type, size_t count, const void* data, size_t bytes);
    std::vector<uint8_t> bytes_;
    uint32_t sections_ = 0;
};

std::string base64(std::span<const uint8_t> bytes);

}  // namespace rtlab::viewer
