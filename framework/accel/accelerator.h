// The interface every acceleration structure implements (brute force, the BVH family, the
// grid, later the trees): build once over a primitive set, then answer closest-hit and any-hit
// queries. Work is counted through the Traversal context (framework/interface/traversal.h).
#pragma once

#include "framework/accel/point_queries.h"
#include "framework/accel/primitive_set.h"
#include "framework/accel/structure_view.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/traversal_stats.h"

#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rtlab {

class Accelerator {
public:
    virtual ~Accelerator() = default;

    virtual void build(const PrimitiveSet& primitives) = 0;
    // Closest hit in (ray.tMin, ray.tMax]; hit.prim == kNoHit on a miss.
    virtual Hit intersect(const Ray& ray, TraversalStats& stats) const = 0;
    // Any hit in (ray.tMin, ray.tMax]: for shadow rays.
    virtual bool occluded(const Ray& ray, TraversalStats& stats) const = 0;
    // Faster queries along rays that start or end at point, made after build; nullptr (the
    // default) when the structure has none, and then intersect() and occluded() answer them.
    virtual std::unique_ptr<PointQueries> queriesAt(const Vec3& point) const {
        (void)point;
        return nullptr;
    }
    virtual StructureView structure() const = 0;
    // Bytes the structure keeps beyond the primitive set (nodes, index lists, copies).
    virtual size_t memoryBytes() const = 0;
};

// One option's value: a number, or one of the words the option takes.
using AcceleratorValue = std::variant<double, std::string>;

// What --accel and its companion flags ask for: a structure's name with its options
// ("grid:C=9", "bvh:split=sah,leaf=8" or an older spelling such as "bvh-sah"), which the
// accelerator registry parses (accelerator_registry.h), and the options flags set on top of the
// name's, typed as the flags read them. Which options a structure has is its own business: the
// spec names none.
struct AcceleratorSpec {
    // An option a command-line flag set: `--max-leaf 8` sets leaf to 8. The flag, as written,
    // names it in errors; one the structure does not have is an error.
    struct FlagSetting {
        std::string flag;
        std::string key;
        AcceleratorValue value;
    };

    std::string name = "bvh-buckets";
    std::vector<FlagSetting> flags = {};  // initialised, so AcceleratorSpec{name} says every member

    // Sets key as flag does, over the name's value and any earlier flag's.
    AcceleratorSpec& set(const std::string& flag, const std::string& key, double number);
    AcceleratorSpec& set(const std::string& flag, const std::string& key, const std::string& word);
    // The flag that set key, or nullptr.
    const FlagSetting* flagSetting(std::string_view key) const;
};

// The accelerator spec asks for, not yet built over anything. Throws rtlab::Error naming the
// problem (and the valid names) when spec names no accelerator; checkAccelerator
// (accelerator_registry.h) says the same without making one.
std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec);

// The structures and options this executable knows, one line each, for help texts.
std::string acceleratorNames();

}  // namespace rtlab
