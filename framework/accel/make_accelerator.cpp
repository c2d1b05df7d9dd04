// Turns an --accel name and its companion flags into an accelerator, through the registry.
#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/error.h"

#include <algorithm>

namespace rtlab {
namespace {

struct ParsedName {
    const AcceleratorType* type = nullptr;
    std::string options;  // "k=v,k=v"
};

// True for the name of a structure of fast/, which this executable may have been linked
// without: a wide BVH ("bvh" and a width, e.g. "bvh4", or fastbvh) or the tuned grid.
bool isFastPathName(std::string_view name) {
    bool wideBvh = name.size() > 3 && name.starts_with("bvh") &&
                   std::all_of(name.begin() + 3, name.end(), [](char c) { return c >= '0' && c <= '9'; });
    return wideBvh || name == "fastbvh" || name == "fastgrid";
}

ParsedName parseName(const std::string& name) {
    size_t colon = name.find(':');
    std::string base = name.substr(0, colon);
    std::string rest = colon == std::string::npos ? "" : name.substr(colon + 1);
    ParsedName parsed{findAcceleratorType(base), rest};
    // The older spelling <type>-<split>[:<B>]: bvh-median, bvh-buckets:12, bvh4-sah.
    size_t dash = base.find('-');
    if (!parsed.type && dash != std::string::npos) {
        std::string typeName = base.substr(0, dash), split = base.substr(dash + 1);
        parsed.type = findAcceleratorType(typeName);
        if (parsed.type && parsed.type->option("split")) {
            if (!rest.empty() && split != "buckets")
                throw Error("--accel " + name + ": only bvh-buckets takes a bucket count after ':'");
            parsed.options = "split=" + split + (rest.empty() ? "" : ",B=" + rest);
        } else {
            parsed.type = nullptr;
            base = typeName;
        }
    }
    if (!parsed.type && isFastPathName(base))
        throw Error("--accel " + name + ": " + base + " is a fast path of fast/, built only into rtlab-solution and the benchmarks");
    if (!parsed.type) {
        std::string names;
        for (const AcceleratorType* type : acceleratorTypes()) names += (names.empty() ? "" : ", ") + type->name;
        throw Error("--accel " + name + " is not an accelerator (valid: " + names + ", with key=value options; see --help)");
    }
    return parsed;
}

// A flag of the command line set to something other than its default names an option the
// structure must have; it overrides the name's value.
void applyFlag(const AcceleratorType& type, const std::string& name, std::string& options, const char* key,
               const std::string& value, const std::string& flag) {
    if (!type.option(key)) throw Error(flag + " is not an option of " + name + " (its structure has no '" + key + "')");
    // Replace a value the name gave, so the flag wins and the key is not given twice.
    std::string rebuilt;
    size_t begin = 0;
    while (begin < options.size()) {
        size_t end = std::min(options.find(',', begin), options.size());
        std::string item = options.substr(begin, end - begin);
        if (!item.starts_with(std::string(key) + "=")) rebuilt += (rebuilt.empty() ? "" : ",") + item;
        begin = end + 1;
    }
    options = rebuilt + (rebuilt.empty() ? "" : ",") + key + "=" + value;
}

}  // namespace

std::string acceleratorNames() {
    std::string text;
    for (const AcceleratorType* type : acceleratorTypes()) {
        text += "  " + type->name + ": " + type->description;
        for (const AcceleratorOption& o : type->options)
            text += "\n      " + o.key + "=" + o.rangeText() + " (default " + o.defaultValue + "): " + o.description;
        text += "\n";
    }
    return text + "  older names: <structure>-<split> and <structure>-buckets:<B>, e.g. bvh-median, bvh-buckets:12";
}

const AcceleratorType& acceleratorTypeOf(const std::string& name) { return *parseName(name).type; }

std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec) {
    if (spec.maxLeaf < 1 || spec.maxLeaf > 65535)
        throw Error("--max-leaf " + std::to_string(spec.maxLeaf) + " is out of range (1..65535)");
    ParsedName parsed = parseName(spec.name);
    const AcceleratorSpec defaults;
    if (spec.maxLeaf != defaults.maxLeaf)
        applyFlag(*parsed.type, spec.name, parsed.options, "leaf", std::to_string(spec.maxLeaf), "--max-leaf");
    if (spec.recursiveTraversal)
        applyFlag(*parsed.type, spec.name, parsed.options, "traversal", "recursive", "--traversal recursive");
    if (spec.sahAllAxes) applyFlag(*parsed.type, spec.name, parsed.options, "axes", "all", "--sah-axes all");
    return parsed.type->make(parsed.type->parameters(parsed.options, spec.name));
}

}  // namespace rtlab
