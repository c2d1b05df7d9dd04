// libFuzzer target: ReferenceData::load, the grader's reference values (grader/reference/structures.json
// and the manifest holding its SHA-256). The input is structures.json; its manifest is written with
// the matching hash, so the entries themselves are parsed, except when the input's first byte
// is odd: then the first half of the rest is the manifest, unchecked, and the second half structures.json.
#include "framework/core/sha256.h"
#include "fuzz/input_file.h"
#include "grader/engine/reference_data.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rtlab;
    if (size == 0) return 0;
    std::string directory = fuzz::scratchDirectory().string();
    const uint8_t* body = data + 1;
    size_t bodySize = size - 1;
    if (data[0] & 1) {
        size_t half = bodySize / 2;
        fuzz::writeInputFile("manifest.json", body, half);
        fuzz::writeInputFile("structures.json", body + half, bodySize - half);
    } else {
        std::string manifest = "{\"structures.json\": \"" +
                               sha256Hex(std::string(reinterpret_cast<const char*>(body), bodySize)) + "\"}";
        fuzz::writeInputFile("manifest.json", reinterpret_cast<const uint8_t*>(manifest.data()), manifest.size());
        fuzz::writeInputFile("structures.json", body, bodySize);
    }
    // Problems are kept, not thrown, and every lookup reports them as one line.
    grader::ReferenceData reference = grader::ReferenceData::load(directory);
    std::string whyNot;
    for (const char* key : {"cornell-box/bvh-sah", "", "x"})
        if (!reference.find(key, "0", &whyNot) && (whyNot.empty() || whyNot.find('\n') != std::string::npos))
            std::abort();
    return 0;
}
