#include "cli/accelerator_options.h"

#include "framework/accel/bvh_accelerator.h"
#include "framework/interface/bvh.h"

namespace rtlab::cli {

void addAcceleratorOptions(CLI::App* command, AcceleratorSpec& spec, const std::string& accelWhat) {
    // The names come from the accelerators this executable links (accelerator_registry.h), so
    // rtlab's help does not offer the fast paths only rtlab-solution has.
    command->add_option("--accel", spec.name, accelWhat + ", one of:\n" + acceleratorNames())->capture_default_str();
    command
        ->add_option_function<int>("--max-leaf", [&spec](int leaf) { setMaxLeaf(spec, leaf); }, "Largest leaf a BVH may keep unsplit")
        ->default_str(std::to_string(BvhOptions().maxLeaf));
    command
        ->add_option_function<std::string>(
            "--traversal", [&spec](const std::string& order) { setTraversal(spec, order); },
            "BVH traversal order: ordered (default) or recursive (the lecture's pseudocode)")
        ->check(CLI::IsMember({"ordered", "recursive"}));
    command
        ->add_option_function<std::string>(
            "--sah-axes", [&spec](const std::string& axes) { setSahAxes(spec, axes); },
            "SAH axes: longest (default, the longest centroid axis) or all (x, y and z)")
        ->check(CLI::IsMember({"longest", "all"}));
}

}  // namespace rtlab::cli
