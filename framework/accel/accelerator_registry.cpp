#include "framework/accel/accelerator_registry.h"

#include "framework/core/error.h"

#include <algorithm>
#include <charconv>
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

std::string formatNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

bool parseNumber(const std::string& text, double* value) {
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *value);
    return ec == std::errc() && end == text.data() + text.size();
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

const std::string& AcceleratorParameters::word(const std::string& key) const { return values_.at(key); }

double AcceleratorParameters::number(const std::string& key) const {
    double value = 0.0;
    parseNumber(values_.at(key), &value);  // validated when the parameters were made
    return value;
}

const AcceleratorOption* AcceleratorType::option(std::string_view key) const {
    for (const AcceleratorOption& o : options)
        if (o.key == key) return &o;
    return nullptr;
}

AcceleratorParameters AcceleratorType::parameters(const std::string& text, const std::string& fullName) const {
    AcceleratorParameters parameters;
    for (const AcceleratorOption& o : options) parameters.values_[o.key] = o.defaultValue;
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
        double number = 0.0;
        bool valid = o->words.empty()
                         ? parseNumber(value, &number) && number >= o->min && number <= o->max &&
                               (!o->integer || number == double(static_cast<long>(number)))
                         : std::find(o->words.begin(), o->words.end(), value) != o->words.end();
        if (!valid)
            throw Error("--accel " + fullName + ": " + key + " must be " +
                        (o->words.empty() ? std::string(o->integer ? "an integer in " : "a number in ") : "one of ") +
                        o->rangeText() + ", not '" + value + "'");
        parameters.values_[key] = value;
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
