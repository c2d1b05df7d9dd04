// The stub tables the grader names stubs from (grader/engine/stub_table.h) against the stubs
// themselves: every function a table lists throws NotImplemented with exactly the name the
// table gives it, in the file the table says, and no stub in assignments/ is missing from its
// assignment's table.
#include "grader/engine/assignment_registry.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace fs = std::filesystem;
using namespace rtlab::grader;

namespace {

std::string read(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Every name a stub file's NotImplemented carries.
std::set<std::string> thrownNames(const fs::path& folder) {
    std::set<std::string> names;
    const std::string open = "NotImplemented(\"";
    for (const auto& entry : fs::directory_iterator(folder)) {
        std::string text = read(entry.path());
        for (size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
            size_t start = at + open.size(), end = text.find('"', start);
            if (end != std::string::npos && end > start && text.compare(end, 2, "\")") == 0) names.insert(text.substr(start, end - start));
        }
    }
    return names;
}

}  // namespace

TEST_CASE("stub tables: every stub named as it names itself, none left out") {
    const fs::path source = RTLAB_SOURCE_DIR;
    for (const Assignment& a : assignments()) {
        const StubTable& table = a.stubs();
        CAPTURE(a.id);
        CHECK(table.assignment() == a.id);
        CHECK(table.folder() == a.folders.back());
        std::set<std::string> listed;
        for (const StubFile& file : table.files()) {
            std::string text = read(source / table.path(file.file));
            CHECK_MESSAGE(!text.empty(), std::string(table.path(file.file) + " is missing"));
            for (const std::string& function : file.functions) {
                std::string name = table.name(function);
                CHECK_MESSAGE(text.find("NotImplemented(\"" + name + "\")") != std::string::npos, std::string(name + " is not what its stub throws"));
                listed.insert(name);
            }
        }
        for (const std::string& thrown : thrownNames(source / "assignments" / table.folder()))
            CHECK_MESSAGE(listed.count(thrown) == 1, std::string(thrown + " is not in " + a.id + "'s stub table"));
    }
}

TEST_CASE("stub tables: names made of several stubs") {
    const Assignment* a3 = findAssignment("a3");
    REQUIRE(a3 != nullptr);
    CHECK(a3->stubs().names({"ddaSetup", "ddaStep"}) == "a3 ddaSetup and ddaStep (assignments/a3_grid/grid_dda.cpp)");
    CHECK(a3->stubs().function("intersectGrid") == "a3 intersectGrid");
    CHECK_THROWS_AS(a3->stubs().name("intersectOctree"), std::logic_error);
    CHECK_THROWS_AS(a3->stubs().names({"ddaSetup", "intersectGrid"}), std::logic_error);
}
