// libFuzzer target: Rubric::load, the instructor-edited points file, then apply() on a few
// test names so the loaded patterns are matched too.
#include "fuzz/input_file.h"
#include "fuzz/one_line_error.h"
#include "grader/engine/rubric.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rtlab::grader;
    std::string path = rtlab::fuzz::writeInputFile("rubric.json", data, size);
    rtlab::fuzz::parseOrReject(path, [](const std::string& file) {
        Rubric rubric = Rubric::load(file);
        std::vector<TestResult> results(3);
        results[0].name = "a0/slab/face-planes";
        results[1].name = "a1/bvh/structure";
        results[2].name = "";
        results[1].fraction = 0.5;
        rubric.apply(results);
        for (const TestResult& result : results)
            if (!(result.maxScore >= 0.0) || std::isnan(result.score)) std::abort();
    });
    return 0;
}
