#include "framework/pov/pov_format.h"

#include "framework/core/shortest_decimal.h"

namespace rtlab::pov {
namespace {

constexpr const char* kWhat = "POV-Ray export";

}  // namespace

std::string number(double value) { return shortestDecimal(value, kWhat); }
std::string number32(float value) { return shortestDecimal32(value, kWhat); }

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
