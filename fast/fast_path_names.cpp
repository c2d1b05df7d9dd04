// The names of fast/'s structures (registered in wide_bvh_layouts.cpp, fast_bvh.cpp and
// fast_grid_accelerator.cpp), for the executables that leave fast/ out: the student's rtlab
// links this file alone, so `--accel bvh4` there says where bvh4 is instead of that it does not
// exist. A structure added to fast/ adds its name here; test_fast_bvh checks that every
// structure fast/ registers is listed.
#include "framework/accel/accelerator_registry.h"

namespace rtlab {
namespace {

const AcceleratorsElsewhere kFastPaths{{"bvh4", "bvh8", "fastbvh", "fastgrid"},
                                       "a fast path of fast/, built only into rtlab-solution and the benchmarks"};

}  // namespace
}  // namespace rtlab
