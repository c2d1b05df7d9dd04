// Errors the framework reports. Every user-facing failure is one of these, carrying a one-line
// message that names the file or flag and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace rtlab {

// Bad input: a missing or malformed file, a wrong flag, NaN vertices, ...
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Thrown by every assignment stub until the student fills it in. The grader reports a test
// that ends in NotImplemented as "not started".
struct NotImplemented : std::logic_error {
    explicit NotImplemented(const std::string& stubName)
        : std::logic_error(stubName + " is not implemented yet"), stub(stubName) {}
    std::string stub;  // e.g. "a0 intersectBox (assignments/a0_intersect/ray_box.cpp)"
};

}  // namespace rtlab
