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
    if (const std::string* where = parsed.type ? nullptr : whereAcceleratorIs(base))
        throw Error("--accel " + name + ": " + base + " is " + *where);
    if (!parsed.type) {
        std::string names;
        for (const AcceleratorType* type : acceleratorTypes()) names += (names.empty() ? "" : ", ") + type->name;
        throw Error("--accel " + name + " is not an accelerator (valid: " + names + ", with key=value options; see --help)");
    }
    return parsed;
}

template <typename Value>
AcceleratorSpec& setFlag(AcceleratorSpec& spec, const std::string& flag, const std::string& key, Value value) {
    std::erase_if(spec.flags, [&key](const AcceleratorSpec::FlagSetting& f) { return f.key == key; });
    spec.flags.push_back({flag, key, AcceleratorValue(std::move(value))});
    return spec;
}

}  // namespace

AcceleratorSpec& AcceleratorSpec::set(const std::string& flag, const std::string& key, double number) {
    return setFlag(*this, flag, key, number);
}

AcceleratorSpec& AcceleratorSpec::set(const std::string& flag, const std::string& key, const std::string& word) {
    return setFlag(*this, flag, key, word);
}

const AcceleratorSpec::FlagSetting* AcceleratorSpec::flagSetting(std::string_view key) const {
    auto found = std::find_if(flags.begin(), flags.end(), [key](const FlagSetting& f) { return f.key == key; });
    return found == flags.end() ? nullptr : &*found;
}

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

AcceleratorChoice chooseAccelerator(const AcceleratorSpec& spec) {
    ParsedName parsed = parseName(spec.name);
    return {parsed.type, parsed.type->parameters(parsed.options, spec)};
}

std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec) {
    AcceleratorChoice choice = chooseAccelerator(spec);
    return choice.type->make(choice.parameters);
}

}  // namespace rtlab
