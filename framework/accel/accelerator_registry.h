// The one list of acceleration structures (docs/conventions.md#accelerator-names). Each
// structure registers its name, its typed options and a factory; --accel parsing, the help of
// render, hits and bench, and the bench's rows all come from here.
//
// A name is the structure, then its options: `grid`, `grid:C=9`, `bvh:split=buckets,B=12`.
// The older spellings stay valid: `<type>-<split>` for a structure with a `split` option
// (bvh-median, bvh4-sah) and `<type>-buckets:<B>` (bvh-buckets:12).
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/structure_drawing.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

// One key=value option: a number in [min, max] (integer or real), or one of a few words.
struct AcceleratorOption {
    std::string key;
    std::string description;
    std::string defaultValue;
    double min = 0.0, max = 0.0;
    bool integer = false;
    std::vector<std::string> words;  // non-empty: the value must be one of these

    std::string rangeText() const;   // "2..32", "1..1000", "median|middle|..."
};

// The validated values of every option of one structure (defaults filled in).
class AcceleratorParameters {
public:
    const std::string& word(const std::string& key) const;
    double number(const std::string& key) const;
    int integer(const std::string& key) const { return static_cast<int>(number(key)); }

private:
    friend struct AcceleratorType;
    std::map<std::string, std::string> values_;
};

struct AcceleratorType {
    std::string name;         // "grid"
    std::string description;  // one line for --help
    std::vector<AcceleratorOption> options;
    std::function<std::unique_ptr<Accelerator>(const AcceleratorParameters&)> make;
    std::vector<std::string> benchRows;  // the names the throughput benchmark runs
    // How fast it renders on this build, among the tuned structures of fast/ (0: not one).
    // rtlab-solution renders with the highest-ranked by default; students' structures are 0.
    int speedRank = 0;
    // How the viewer draws its StructureView (structure_drawing.h), defined beside the
    // structure; null: drawLevels, a tree of boxes.
    StructureDrawer draw = nullptr;

    const AcceleratorOption* option(std::string_view key) const;
    // Parses "k=v,k=v" (empty for all defaults); throws rtlab::Error naming what is wrong.
    AcceleratorParameters parameters(const std::string& text, const std::string& fullName) const;
};

// Adds a structure; a second one with the same name is a programming error and aborts.
void registerAcceleratorType(AcceleratorType type);
// Registers during static initialisation (the fast/ structures): `static AcceleratorRegistration r{...};`
struct AcceleratorRegistration {
    explicit AcceleratorRegistration(AcceleratorType type) { registerAcceleratorType(std::move(type)); }
};

const AcceleratorType* findAcceleratorType(std::string_view name);
// The structure a full --accel name builds ("bvh-median", "grid:C=9": bvh, grid); throws
// rtlab::Error as makeAccelerator does for a name it cannot build (make_accelerator.cpp).
const AcceleratorType& acceleratorTypeOf(const std::string& name);
// Every structure this executable has, the framework's first, then the registered ones by name.
std::vector<const AcceleratorType*> acceleratorTypes();

// The structure with the highest speedRank above 0, or nullptr when this executable has none
// (the student's rtlab, which leaves fast/ out).
const AcceleratorType* fastestAcceleratorType();
// What renders without --accel: the fastest structure, else AcceleratorSpec's default.
std::string defaultRenderAccelerator();

// The option lists of the binary BVH, shared with the other traversals of the same tree.
std::vector<AcceleratorOption> bvhTreeOptions();

}  // namespace rtlab
