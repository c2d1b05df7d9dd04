#include "framework/pov/pov_format.h"

#include "framework/core/error.h"

#include <charconv>
#include <cmath>

namespace rtlab::pov {
namespace {

template <typename Float>
std::string shortestRoundTrip(Float value) {
    if (!std::isfinite(value)) throw Error("POV-Ray export: non-finite value " + std::to_string(value));
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

}  // namespace

std::string number(double value) { return shortestRoundTrip(value); }
std::string number32(float value) { return shortestRoundTrip(value); }

// Appended piece by piece ("<" + std::string trips GCC 12's -Wrestrict false positive).
template <typename V, typename Format>
std::string bracketed(const V& v, Format format) {
    std::string text(1, '<');
    text.append(format(v.x)).append(1, ',').append(format(v.y)).append(1, ',').append(format(v.z));
    text.append(1, '>');
    return text;
}

std::string vector(const DVec3& v) { return bracketed(v, number); }
std::string vector32(const Vec3& v) { return bracketed(v, number32); }

}  // namespace rtlab::pov
