// The glTF loader's limits on input (framework/scene/gltf_loader.cpp): documents that ask for
// far more than they hold (tests/data/make-test-data.py writes them) end in one line naming the
// file and the problem, and no single allocation on the way is large. This executable counts
// every operator new to show the second half.
#include "framework/core/error.h"
#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include <sys/stat.h>

namespace {

std::atomic<size_t> largestAllocation{0};

void* allocate(size_t size) {
    size_t seen = largestAllocation.load();
    while (size > seen && !largestAllocation.compare_exchange_weak(seen, size)) {
    }
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(size_t size) { return allocate(size); }
void* operator new[](size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }

namespace {

// Far below what any of the documents asks for, far above what loading a small file needs.
constexpr size_t kLargeAllocation = size_t{64} << 20;

std::string dataFile(const std::string& name) { return std::string(RTLAB_SOURCE_DIR) + "/tests/data/" + name; }

// The message loading path fails with; fails the test if it loads, throws something other than
// rtlab::Error, allocates kLargeAllocation bytes at once, or the message is not one line
// starting with the path.
std::string loadError(const std::string& path) {
    CAPTURE(path);
    largestAllocation = 0;
    std::string message;
    try {
        rtlab::loadGltf(path);
        FAIL("loaded without an error");
    } catch (const rtlab::Error& e) {
        message = e.what();
    }
    CAPTURE(message);
    CHECK(largestAllocation.load() < kLargeAllocation);
    CHECK(message.rfind(path + ": ", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
    return message;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("glTF limits: a buffer byteLength of 2^40 bytes behind 36 bytes of data") {
    for (const char* name : {"huge-buffer.gltf", "huge-buffer.glb"}) {
        std::string message = loadError(dataFile(name));
        CAPTURE(message);
        CHECK(contains(message, "buffer 0: byteLength 1099511627776 is more than the"));
    }
}

TEST_CASE("glTF limits: an accessor count of 2^32 - 3 in a 36-byte bufferView") {
    std::string message = loadError(dataFile("huge-accessor-count.gltf"));
    CHECK(contains(message, "accessor 0: 4294967293 elements reach past the end of bufferView 0 (36 bytes)"));
}

TEST_CASE("glTF limits: a node hierarchy of 1001 levels") {
    std::string message = loadError(dataFile("deep-hierarchy.gltf"));
    CHECK(contains(message, "the node hierarchy is deeper than 1000 levels (at node 1000 'level1001')"));
}

TEST_CASE("glTF limits: a cycle in the node graph that no scene reaches") {
    std::string message = loadError(dataFile("cycle.gltf"));
    CHECK(contains(message, "node 1 'a' is on a cycle of the node hierarchy"));
}

TEST_CASE("glTF limits: extras nested 10000 levels deep") {
    std::string message = loadError(dataFile("deep-json.gltf"));
    CHECK(contains(message, "JSON nests deeper than 64 levels"));
}

TEST_CASE("glTF limits: a buffer uri naming a FIFO, whose read would block forever") {
    std::filesystem::path directory = std::filesystem::path(RTLAB_BINARY_DIR) / "tests" / "gltf-limits";
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    REQUIRE(mkfifo((directory / "pipe.bin").c_str(), 0600) == 0);
    std::string path = (directory / "fifo-buffer.gltf").string();
    std::ofstream(path) << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "pipe.bin", "byteLength": 12}]})";
    std::string message = loadError(path);
    CHECK(contains(message, "pipe.bin : not a regular file"));
}

TEST_CASE("glTF limits: a buffer naming a file of 2 GiB") {
    std::filesystem::path directory = std::filesystem::path(RTLAB_BINARY_DIR) / "tests" / "gltf-limits-large";
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    std::ofstream(directory / "large.bin").close();
    std::filesystem::resize_file(directory / "large.bin", uintmax_t{2} << 30);  // sparse: no disk used
    std::string path = (directory / "large-buffer.gltf").string();
    std::ofstream(path) << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "large.bin", "byteLength": 12}]})";
    std::string message = loadError(path);
    CHECK(contains(message, "large.bin : beyond the loader's limit of 1024 MiB for a scene and the files it names"));
    std::filesystem::remove_all(directory);
}

TEST_CASE("glTF limits: the files within them still load") {
    largestAllocation = 0;
    rtlab::Scene scene = rtlab::loadGltf(dataFile("hierarchy.glb"));
    CHECK(scene.triangleCount() == 4);
    CHECK(largestAllocation.load() < kLargeAllocation);
}
