// Turns an --accel name into an accelerator.
#include "framework/accel/accelerator.h"
#include "framework/accel/brute_force.h"
#include "framework/accel/bvh_accelerator.h"
#include "framework/accel/bvh_layouts.h"
#include "framework/core/error.h"

#include <charconv>

namespace rtlab {

std::string acceleratorNames() {
    std::string names = "brute, bvh-median, bvh-middle, bvh-equal, bvh-sah, bvh-buckets[:B] with B in 2..32";
    for (const BvhLayout* layout : bvhLayouts())
        names += ", " + layout->prefix + "-<method> (" + layout->description + ")";
    return names;
}

std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec) {
    if (spec.maxLeaf < 1 || spec.maxLeaf > 65535)
        throw Error("--max-leaf " + std::to_string(spec.maxLeaf) + " is out of range (1..65535)");
    if (spec.name == "brute") return std::make_unique<BruteForce>();

    BvhOptions options;
    options.maxLeaf = spec.maxLeaf;
    options.allAxes = spec.sahAllAxes;
    // <layout>-<method>: the tree bvh-<method> builds, traversed by the layout named before the
    // dash (bvh is the binary traversal, others are registered in bvh_layouts.h).
    size_t dash = spec.name.find('-');
    std::string prefix = dash == std::string::npos ? "" : spec.name.substr(0, dash);
    const BvhLayout* layout = findBvhLayout(prefix);
    // An executable without the fast paths names them; one with them lists what it has.
    if (!layout && bvhLayouts().empty() && isWideBvhPrefix(prefix))
        throw Error("--accel " + spec.name +
                    ": the wide BVHs are fast paths, built only into rtlab-solution and the benchmarks");
    std::string name = layout ? "bvh" + spec.name.substr(dash) : spec.name;
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
    else throw Error("--accel " + spec.name + " is not an accelerator (valid: " + acceleratorNames() + ")");
    if (!layout) return std::make_unique<BvhAccelerator>(options, spec.recursiveTraversal);
    if (spec.recursiveTraversal)
        throw Error("--traversal recursive applies to the binary BVH only, not to " + spec.name);
    return layout->make(options);
}

}  // namespace rtlab
