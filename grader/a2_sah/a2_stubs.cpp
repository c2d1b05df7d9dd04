#include "grader/a2_sah/a2_tests.h"

namespace rtlab::grader {

const StubTable& a2Stubs() {
    static const StubTable table{"a2", "a2_sah", {
        {"sah_buckets.cpp", {"splitSahBuckets"}},
        {"sah_sweep.cpp", {"splitSahSweep"}},
    }};
    return table;
}

}  // namespace rtlab::grader
