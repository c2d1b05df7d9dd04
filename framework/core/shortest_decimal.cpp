#include "framework/core/shortest_decimal.h"

#include "framework/core/error.h"

#include <charconv>
#include <cmath>

namespace rtlab {
namespace {

template <typename Float>
std::string shortestRoundTrip(Float value, const char* what) {
    if (!std::isfinite(value)) throw Error(std::string(what) + ": non-finite value " + std::to_string(value));
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

}  // namespace

std::string shortestDecimal(double value, const char* what) { return shortestRoundTrip(value, what); }
std::string shortestDecimal32(float value, const char* what) { return shortestRoundTrip(value, what); }

}  // namespace rtlab
