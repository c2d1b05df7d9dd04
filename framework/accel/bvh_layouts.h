// Traversal layouts of the BVH that assignments a1/a2 build, beyond the binary one the
// framework traverses itself. A layout is named by the prefix of its --accel names
// ("bvh4" gives bvh4-median ... bvh4-buckets:B) and builds an accelerator from the same
// BvhOptions as the binary BVH.
//
// The tuned layouts (the wide BVHs in fast/) register themselves when an executable links
// them: rtlab-solution, the benchmarks and the tests that exercise them do, rtlab does not, so
// the student binary carries no tuned copy of an assignment's answer.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/interface/bvh.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

struct BvhLayout {
    std::string prefix;  // "bvh4": the names are prefix + "-" + a split method
    std::string description;  // for --help: what traverses the tree
    std::unique_ptr<Accelerator> (*make)(const BvhOptions& options);
};

// Adds a layout; a second layout with the same prefix, or the binary "bvh", is a programming
// error and aborts at start-up.
void registerBvhLayout(BvhLayout layout);

// The layout with this prefix, or nullptr.
const BvhLayout* findBvhLayout(std::string_view prefix);

// Every registered layout, by prefix.
std::vector<const BvhLayout*> bvhLayouts();

// True for a prefix shaped like a wide layout's ("bvh" and a width, e.g. "bvh4"), registered
// or not: such a name is a fast path that this executable was linked without.
bool isWideBvhPrefix(std::string_view prefix);

// Registers a layout during static initialisation: `static BvhLayoutRegistration r{{...}};`.
struct BvhLayoutRegistration {
    explicit BvhLayoutRegistration(BvhLayout layout) { registerBvhLayout(std::move(layout)); }
};

}  // namespace rtlab
