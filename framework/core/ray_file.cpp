#include "framework/core/ray_file.h"

#include "framework/core/error.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

namespace rtlab {
namespace {

// Parses one whitespace-free token as a float; accepts a leading '+'. Returns the problem, or
// an empty string: a value beyond float's range (1e40) would silently become inf, and nan would
// reach the traversal as a ray no test can judge, so both are refused here where the file and
// line are known. inf is the one non-finite value a ray has: tmax (column 8, the default).
std::string parseFloat(const std::string& token, bool mayBeInfinite, float* value) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first != last && *first == '+') ++first;
    auto [end, ec] = std::from_chars(first, last, *value);
    if (ec == std::errc::result_out_of_range && end == last) return "'" + token + "' is out of float range";
    if (ec != std::errc() || end != last) return "'" + token + "' is not a float";
    if (std::isnan(*value)) return "'" + token + "' is not a number (nan is not a ray coordinate)";
    if (std::isinf(*value) && !mayBeInfinite) return "'" + token + "' is infinite (only tmax, the 8th number, may be inf)";
    return {};
}

}  // namespace

std::vector<Ray> readRayFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open the ray file");
    std::vector<Ray> rays;
    std::string line;
    for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {  // a huge file must not overflow it
        line = line.substr(0, line.find('#'));
        std::istringstream tokens(line);
        std::vector<float> numbers;
        for (std::string token; tokens >> token;) {
            float value;
            std::string problem = parseFloat(token, numbers.size() == 7, &value);
            if (!problem.empty()) throw Error(path + ":" + std::to_string(lineNumber) + ": " + problem);
            numbers.push_back(value);
        }
        if (numbers.empty()) continue;
        if (numbers.size() != 6 && numbers.size() != 8)
            throw Error(path + ":" + std::to_string(lineNumber) + ": expected 6 or 8 numbers (ox oy oz dx dy dz [tmin tmax]), found " +
                        std::to_string(numbers.size()));
        Ray ray;
        ray.origin = {numbers[0], numbers[1], numbers[2]};
        ray.direction = {numbers[3], numbers[4], numbers[5]};
        if (numbers.size() == 8) {
            ray.tMin = numbers[6];
            ray.tMax = numbers[7];
        }
        rays.push_back(ray);
    }
    if (in.bad()) throw Error(path + ": read error");
    return rays;
}

void writeRayFile(const std::string& path, const std::vector<Ray>& rays) {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "w"), std::fclose);
    if (!file) throw Error(path + ": cannot write the ray file");
    std::fputs("# ox oy oz dx dy dz tmin tmax\n", file.get());
    for (const Ray& r : rays)
        std::fprintf(file.get(), "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", r.origin.x, r.origin.y, r.origin.z,
                     r.direction.x, r.direction.y, r.direction.z, r.tMin, r.tMax);
    if (std::ferror(file.get())) throw Error(path + ": write error");
}

}  // namespace rtlab
