// Turns an --accel name into an accelerator.
#include "framework/accel/accelerator.h"
#include "framework/accel/brute_force.h"
#include "framework/accel/bvh_accelerator.h"
#include "framework/accel/wide_bvh_accelerator.h"
#include "framework/core/error.h"

#include <charconv>

namespace rtlab {

static constexpr const char* kValidNames =
    "brute, bvh-median, bvh-middle, bvh-equal, bvh-sah, bvh-buckets[:B] with B in 2..32, and the "
    "same with bvh4- or bvh8- for the four- or eight-wide BVH";

std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec) {
    if (spec.maxLeaf < 1 || spec.maxLeaf > 65535)
        throw Error("--max-leaf " + std::to_string(spec.maxLeaf) + " is out of range (1..65535)");
    if (spec.name == "brute") return std::make_unique<BruteForce>();

    BvhOptions options;
    options.maxLeaf = spec.maxLeaf;
    options.allAxes = spec.sahAllAxes;
    // bvh4-<method> and bvh8-<method> traverse the tree bvh-<method> builds, four or eight wide.
    int width = spec.name.starts_with("bvh4-") ? 4 : spec.name.starts_with("bvh8-") ? 8 : 2;
    std::string name = width > 2 ? "bvh-" + spec.name.substr(5) : spec.name;
    if (name.starts_with("bvh-buckets:")) {
        std::string count = name.substr(12);
        auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), options.buckets);
        if (ec != std::errc() || end != count.data() + count.size() || options.buckets < 2 ||
            options.buckets > 32)
            throw Error("--accel " + spec.name + ": the bucket count must be an integer in 2..32");
        name = "bvh-buckets";
    }
    if (name == "bvh-median") options.method = SplitMethod::Median;
    else if (name == "bvh-middle") options.method = SplitMethod::Middle;
    else if (name == "bvh-equal") options.method = SplitMethod::EqualCounts;
    else if (name == "bvh-sah") options.method = SplitMethod::SahSweep;
    else if (name == "bvh-buckets") options.method = SplitMethod::SahBuckets;
    else throw Error("--accel " + spec.name + " is not an accelerator (valid: " + kValidNames + ")");
    if (width == 2) return std::make_unique<BvhAccelerator>(options, spec.recursiveTraversal);
    if (spec.recursiveTraversal)
        throw Error("--traversal recursive applies to the binary BVH only, not to " + spec.name);
    if (width == 4) return std::make_unique<WideBvhAccelerator<4>>(options);
    return std::make_unique<WideBvhAccelerator<8>>(options);
}

}  // namespace rtlab
