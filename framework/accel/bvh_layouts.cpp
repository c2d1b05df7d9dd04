#include "framework/accel/bvh_layouts.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace rtlab {
namespace {

// Function-local, so that registrations from other files' static initialisers find it built
// whatever order the linker puts those files in.
std::vector<BvhLayout>& registry() {
    static std::vector<BvhLayout> layouts;
    return layouts;
}

}  // namespace

void registerBvhLayout(BvhLayout layout) {
    if (layout.prefix == "bvh" || findBvhLayout(layout.prefix) || !layout.make) {
        std::fprintf(stderr, "rtlab: BVH layout '%s' registered twice or without a factory\n", layout.prefix.c_str());
        std::abort();
    }
    registry().push_back(std::move(layout));
}

const BvhLayout* findBvhLayout(std::string_view prefix) {
    for (const BvhLayout& layout : registry())
        if (layout.prefix == prefix) return &layout;
    return nullptr;
}

std::vector<const BvhLayout*> bvhLayouts() {
    std::vector<const BvhLayout*> layouts;
    for (const BvhLayout& layout : registry()) layouts.push_back(&layout);
    std::sort(layouts.begin(), layouts.end(), [](auto* a, auto* b) { return a->prefix < b->prefix; });
    return layouts;
}

bool isWideBvhPrefix(std::string_view prefix) {
    return prefix.size() > 3 && prefix.starts_with("bvh") &&
           std::all_of(prefix.begin() + 3, prefix.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace rtlab
