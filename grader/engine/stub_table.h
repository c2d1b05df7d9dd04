// The stubs of one assignment's student files: the one table the grader takes the names in its
// verdicts from ("crashed with SIGSEGV in a3 gridResolution (assignments/a3_grid/grid_build.cpp)"),
// the very text each stub's NotImplemented carries, so a verdict and a not-started report name
// the same thing. tests/test_stub_names.cpp checks every table against the stubs it describes.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

namespace rtlab::grader {

struct StubFile {
    std::string file;                    // "grid_build.cpp", in assignments/<folder>/
    std::vector<std::string> functions;  // each throws NotImplemented(name(function))
};

class StubTable {
public:
    StubTable(std::string assignment, std::string folder, std::vector<StubFile> files);

    // "a3 gridResolution (assignments/a3_grid/grid_build.cpp)", what that stub throws.
    std::string name(const std::string& function) const;
    // "a3 ddaSetup and ddaStep (assignments/a3_grid/grid_dda.cpp)": functions of one file.
    std::string names(std::initializer_list<std::string> functions) const;
    // "a6 samplers (assignments/a6_radiometry/samplers.cpp)": a file's stubs under one label.
    std::string file(const std::string& file, const std::string& label) const;
    // "a1 splitMedian": the function without its file, for a name made of several.
    std::string function(const std::string& function) const;

    const std::string& assignment() const { return assignment_; }
    const std::string& folder() const { return folder_; }
    const std::vector<StubFile>& files() const { return files_; }
    // "assignments/a3_grid/grid_build.cpp"
    std::string path(const std::string& file) const;

private:
    // The file holding `function`; std::logic_error when the table has no such stub (a grader
    // bug, found by the first grading run).
    const StubFile& fileOf(const std::string& function) const;

    std::string assignment_, folder_;
    std::vector<StubFile> files_;
};

}  // namespace rtlab::grader
