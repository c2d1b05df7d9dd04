// libFuzzer target: readRayFile, the text format of `rtlab hits --rays`.
#include "framework/core/ray_file.h"
#include "fuzz/input_file.h"
#include "fuzz/one_line_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string path = rtlab::fuzz::writeInputFile("rays.txt", data, size);
    rtlab::fuzz::parseOrReject(path, [](const std::string& file) { rtlab::readRayFile(file); });
    return 0;
}
