// A file a submission lacks comes from the committed stubs (grader/engine/pristine_stubs.h): in a git
// checkout from HEAD, whatever the working tree holds; in an archive, from its assignments/.
#include "grader/engine/pristine_stubs.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

}  // namespace

TEST_CASE("pristine stubs: a git checkout gives the committed files, not the working tree") {
    fs::path repo = fs::temp_directory_path() / ("rtlab-pristine-" + std::to_string(::getpid()));
    fs::remove_all(repo);
    write(repo / "assignments/a0_intersect/ray_box.cpp", "committed stub\n");
    write(repo / "assignments/a0_intersect/notes.txt", "not a source\n");
    std::string git = "git -C '" + repo.string() + "' -c user.name=t -c user.email=t@t ";
    REQUIRE(std::system((git + "init -q && " + git + "add -A && " + git + "commit -q -m stubs").c_str()) == 0);
    write(repo / "assignments/a0_intersect/ray_box.cpp", "filled in by the instructor\n");
    write(repo / "assignments/a0_intersect/extra.cpp", "never committed\n");

    auto stubs = rtlab::grader::pristineStubs(repo.string());
    CHECK(stubs.size() == 1);
    CHECK(stubs["assignments/a0_intersect/ray_box.cpp"] == "committed stub\n");
    // A folder the graded tests call must have a committed stub: an assignment added but not
    // yet committed is named, with what to do. A folder whose name starts like it is not it.
    write(repo / "assignments/a0_intersect_more/extra.cpp", "never committed\n");
    CHECK(rtlab::grader::pristineStubs(repo.string(), {"a0_intersect"}).size() == 1);
    CHECK_THROWS_WITH(rtlab::grader::pristineStubs(repo.string(), {"a0_intersect", "a0_inter"}),
                      doctest::Contains("assignments/a0_inter/ has no committed stub; submissions are built against the stubs at git's HEAD, so commit it first"));
    fs::remove_all(repo / "assignments/a0_intersect_more");

    fs::remove_all(repo / ".git");  // an archive: what is there was made from committed files
    stubs = rtlab::grader::pristineStubs(repo.string());
    CHECK(stubs.size() == 2);
    CHECK(stubs["assignments/a0_intersect/ray_box.cpp"] == "filled in by the instructor\n");
    fs::remove_all(repo);
}
