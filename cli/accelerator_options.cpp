#include "cli/accelerator_options.h"

namespace rtlab::cli {

void addAcceleratorOptions(CLI::App* command, AcceleratorSpec& spec, const std::string& accelWhat) {
    // The names come from the accelerators this executable links (bvh_layouts.h), so rtlab's
    // help does not offer the fast paths only rtlab-solution has.
    command->add_option("--accel", spec.name, accelWhat + ", one of:\n" + acceleratorNames())->capture_default_str();
    command->add_option("--max-leaf", spec.maxLeaf, "Largest leaf a BVH may keep unsplit")
        ->capture_default_str();
    command
        ->add_option_function<std::string>(
            "--traversal", [&spec](const std::string& order) { spec.recursiveTraversal = order == "recursive"; },
            "BVH traversal order: ordered (default) or recursive (the lecture's pseudocode)")
        ->check(CLI::IsMember({"ordered", "recursive"}));
    command
        ->add_option_function<std::string>(
            "--sah-axes", [&spec](const std::string& axes) { spec.sahAllAxes = axes == "all"; },
            "SAH axes: longest (default, the longest centroid axis) or all (x, y and z)")
        ->check(CLI::IsMember({"longest", "all"}));
}

}  // namespace rtlab::cli
