#include "framework/accel/accelerator_registry.h"

#include "framework/core/error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rtlab {

// The framework's structures, each defined beside its accelerator. Adding a structure is its
// folder under framework/accel/ and one line here.
AcceleratorType bruteForceType();  // brute_force.cpp
AcceleratorType bvhType();         // bvh_accelerator.cpp
AcceleratorType gridType();        // grid/grid_accelerator.cpp
AcceleratorType twoLevelGridType();  // grid/two_level_grid_accelerator.cpp
AcceleratorType octreeType();        // octree/octree_accelerator.cpp
AcceleratorType kdTreeType();        // kdtree/kdtree_accelerator.cpp
AcceleratorType bspType();           // bsp/bsp_accelerator.cpp

namespace {

std::vector<AcceleratorType> frameworkTypes() {
    return {bruteForceType(), bvhType(), gridType(), twoLevelGridType(), octreeType(), kdTreeType(), bspType()};
}

// Function-local, so registrations from other files' static initialisers find it built
// whatever order the linker puts those files in.
std::vector<AcceleratorType>& registered() {
    static std::vector<AcceleratorType> types;
    return types;
}

const std::vector<AcceleratorType>& framework() {
    static const std::vector<AcceleratorType> types = frameworkTypes();
    return types;
}

// Names registered as linked elsewhere, with where (AcceleratorsElsewhere).
std::map<std::string, std::string, std::less<>>& elsewhere() {
    static std::map<std::string, std::string, std::less<>> names;
    return names;
}

std::string formatNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

// A flag's value as it was typed: whole numbers in full (1000000, not 1e+06).
std::string flagValueText(double v) {
    return v == std::floor(v) && std::fabs(v) < 1e15 ? std::to_string(static_cast<long long>(v)) : formatNumber(v);
}

}  // namespace

std::string AcceleratorOption::rangeText() const {
    if (!words.empty()) {
        std::string text;
        for (const std::string& w : words) text += (text.empty() ? "" : "|") + w;
        return text;
    }
    return formatNumber(min) + ".." + formatNumber(max);
}

std::optional<AcceleratorValue> AcceleratorOption::parse(const std::string& text) const {
    if (!words.empty()) return text;
    double number = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return number;
}

bool AcceleratorOption::accepts(const AcceleratorValue& value) const {
    if (!words.empty()) {
        const std::string* word = std::get_if<std::string>(&value);
        return word && std::find(words.begin(), words.end(), *word) != words.end();
    }
    const double* number = std::get_if<double>(&value);
    return number && *number >= min && *number <= max && (!integer || *number == std::floor(*number));
}

const AcceleratorOption* AcceleratorType::option(std::string_view key) const {
    for (const AcceleratorOption& o : options)
        if (o.key == key) return &o;
    return nullptr;
}

AcceleratorParameters AcceleratorType::parameters(const std::string& text, const AcceleratorSpec& spec) const {
    const std::string& fullName = spec.name;
    for (const AcceleratorSpec::FlagSetting& flag : spec.flags)
        if (!option(flag.key)) throw Error(flag.flag + " is not an option of " + fullName + " (its structure has no '" + flag.key + "')");
    AcceleratorParameters parameters;
    for (const AcceleratorOption& o : options) parameters.values_[o.key] = *o.parse(o.defaultValue);
    std::vector<std::string> seen;
    size_t begin = 0;
    while (begin < text.size()) {
        size_t end = std::min(text.find(',', begin), text.size());
        std::string item = text.substr(begin, end - begin);
        begin = end + 1;
        size_t equals = item.find('=');
        std::string key = item.substr(0, equals);
        const AcceleratorOption* o = option(key);
        std::string known;
        for (const AcceleratorOption& k : options) known += (known.empty() ? "" : ", ") + k.key;
        if (equals == std::string::npos || !o)
            throw Error("--accel " + fullName + ": '" + item + "' is not an option of " + name +
                        (options.empty() ? " (it has none)" : " (options: " + known + ", each as key=value)"));
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            throw Error("--accel " + fullName + ": " + key + " is given twice");
        seen.push_back(key);
        std::string value = item.substr(equals + 1);
        std::optional<AcceleratorValue> typed = o->parse(value);
        if (!typed || !o->accepts(*typed))
            throw Error("--accel " + fullName + ": " + key + " must be " +
                        (o->words.empty() ? std::string(o->integer ? "an integer in " : "a number in ") : "one of ") +
                        o->rangeText() + ", not '" + value + "'");
        parameters.values_[key] = *typed;
    }
    // A flag wins over the name: `--accel bvh:leaf=2 --max-leaf 8` builds leaves of 8.
    for (const AcceleratorSpec::FlagSetting& flag : spec.flags) {
        const AcceleratorOption* o = option(flag.key);
        if (!o->accepts(flag.value)) {
            const double* number = std::get_if<double>(&flag.value);
            throw Error(number ? flag.flag + " " + flagValueText(*number) + " is out of range (" + o->rangeText() + ")"
                               : flag.flag + " is not one of " + o->rangeText());
        }
        parameters.values_[flag.key] = flag.value;
    }
    return parameters;
}

void registerAcceleratorType(AcceleratorType type) {
    if (findAcceleratorType(type.name) || !type.make) {
        std::fprintf(stderr, "rtlab: accelerator '%s' registered twice or without a factory\n", type.name.c_str());
        std::abort();
    }
    registered().push_back(std::move(type));
}

AcceleratorsElsewhere::AcceleratorsElsewhere(std::vector<std::string> names, std::string where) {
    for (std::string& name : names) elsewhere()[std::move(name)] = where;
}

const std::string* whereAcceleratorIs(std::string_view name) {
    auto found = elsewhere().find(name);
    return found == elsewhere().end() ? nullptr : &found->second;
}

const AcceleratorType* findAcceleratorType(std::string_view name) {
    for (const std::vector<AcceleratorType>* list : {&framework(), static_cast<const std::vector<AcceleratorType>*>(&registered())})
        for (const AcceleratorType& type : *list)
            if (type.name == name) return &type;
    return nullptr;
}

std::vector<const AcceleratorType*> acceleratorTypes() {
    std::vector<const AcceleratorType*> types;
    for (const AcceleratorType& type : framework()) types.push_back(&type);
    std::vector<const AcceleratorType*> others;
    for (const AcceleratorType& type : registered()) others.push_back(&type);
    std::sort(others.begin(), others.end(), [](auto* a, auto* b) { return a->name < b->name; });
    types.insert(types.end(), others.begin(), others.end());
    return types;
}

const AcceleratorType* fastestAcceleratorType() {
    const AcceleratorType* fastest = nullptr;
    for (const AcceleratorType* type : acceleratorTypes())
        if (type->speedRank > 0 && (!fastest || type->speedRank > fastest->speedRank)) fastest = type;
    return fastest;
}

std::string defaultRenderAccelerator() {
    const AcceleratorType* fastest = fastestAcceleratorType();
    return fastest ? fastest->name : AcceleratorSpec().name;
}

std::vector<AcceleratorOption> bvhTreeOptions() {
    return {
        {"split", "split rule: a1's median, middle, equal (counts), a2's sah (full sweep), buckets", "buckets", 0, 0, false,
         {"median", "middle", "equal", "sah", "buckets"}},
        {"B", "SAH buckets (split=buckets)", "12", 2, 32, true, {}},
        {"leaf", "largest leaf a heuristic may keep unsplit", "4", 1, 65535, true, {}},
        {"axes", "SAH axes: the longest centroid axis, or all three", "longest", 0, 0, false, {"longest", "all"}},
    };
}

}  // namespace rtlab
