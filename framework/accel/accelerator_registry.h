// The one list of acceleration structures (docs/conventions.md#accelerator-names). Each
// structure registers its name, its typed options and a factory that reads them (as pbrt-v4's
// BVHAggregate::Create does); --accel parsing, the help of render, hits and bench, and the
// bench's rows and target tables all come from here.
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
#include <optional>
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
    // text as this option's type: a number (nullopt when it is none) or the word itself.
    std::optional<AcceleratorValue> parse(const std::string& text) const;
    // Whether the option takes value: a number in range (whole for an integer option), or one
    // of its words.
    bool accepts(const AcceleratorValue& value) const;
};

// The validated values of every option of one structure (defaults filled in), typed: what a
// structure's factory reads.
class AcceleratorParameters {
public:
    const std::string& word(const std::string& key) const { return std::get<std::string>(values_.at(key)); }
    double number(const std::string& key) const { return std::get<double>(values_.at(key)); }
    int integer(const std::string& key) const { return static_cast<int>(number(key)); }

private:
    friend struct AcceleratorType;
    std::map<std::string, AcceleratorValue> values_;
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
    // The defaults, then the options of text ("k=v,k=v", the part of spec's name after the
    // structure), then spec's flags; throws rtlab::Error naming what is wrong.
    AcceleratorParameters parameters(const std::string& text, const AcceleratorSpec& spec) const;
};

// Adds a structure; a second one with the same name is a programming error and aborts.
void registerAcceleratorType(AcceleratorType type);
// Registers during static initialisation (the fast/ structures): `static AcceleratorRegistration r{...};`
struct AcceleratorRegistration {
    explicit AcceleratorRegistration(AcceleratorType type) { registerAcceleratorType(std::move(type)); }
};

// Names of structures an executable may be linked without (fast/'s, which the student's rtlab
// leaves out), and where they are: "--accel bvh4" there says where bvh4 is rather than that
// no such structure exists. `static AcceleratorsElsewhere r{{"bvh4", ...}, "a fast path of ..."};`
struct AcceleratorsElsewhere {
    AcceleratorsElsewhere(std::vector<std::string> names, std::string where);
};

// Where a structure this executable does not have is, for a name registered so; else nullptr.
const std::string* whereAcceleratorIs(std::string_view name);

const AcceleratorType* findAcceleratorType(std::string_view name);
// The structure a full --accel name builds ("bvh-median", "grid:C=9": bvh, grid); throws
// rtlab::Error as makeAccelerator does for a name it cannot build (make_accelerator.cpp).
const AcceleratorType& acceleratorTypeOf(const std::string& name);

// What a spec asks for, checked and typed: the structure and every option's value, the name's
// and the flags' over the defaults.
struct AcceleratorChoice {
    const AcceleratorType* type;
    AcceleratorParameters parameters;
};
// Checks spec without making anything (a bad --accel fails before a scene is loaded): throws
// rtlab::Error with one line naming the problem, as makeAccelerator does.
AcceleratorChoice chooseAccelerator(const AcceleratorSpec& spec);
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
