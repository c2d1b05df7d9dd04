#include "bench/target_tables.h"

#include "framework/accel/accelerator_registry.h"

#include <map>

namespace rtlab::bench {
namespace {

// Function-local, so registrations from other files' static initialisers find it built.
std::multimap<std::string, TargetTable>& tables() {
    static std::multimap<std::string, TargetTable> byStructure;
    return byStructure;
}

}  // namespace

TargetTableRegistration::TargetTableRegistration(std::string structure, TargetTable table) {
    tables().emplace(std::move(structure), table);
}

void writeStructureTargets(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    for (const AcceleratorType* type : acceleratorTypes()) {
        auto [begin, end] = tables().equal_range(type->name);
        for (auto it = begin; it != end; ++it) it->second(out, records);
    }
}

}  // namespace rtlab::bench
