// libFuzzer target: ReferenceManifest::load, scenes/refs/manifest.json of the POV-Ray references.
#include "framework/external/reference_manifest.h"
#include "fuzz/input_file.h"
#include "fuzz/one_line_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string path = rtlab::fuzz::writeInputFile("manifest.json", data, size);
    rtlab::fuzz::parseOrReject(path, [](const std::string& file) { rtlab::ReferenceManifest::load(file); });
    return 0;
}
