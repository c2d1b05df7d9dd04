// The assignment stubs as committed (docs/grading.md, "Grading a submission"): what a file
// missing from a submission is taken from. In a git checkout they are read from HEAD, never
// from the working tree an instructor may have edited or filled in; a release or a Gradescope
// zip has no .git, but was itself made from committed files only (rtlab release,
// scripts/make-gradescope), so its assignments/ folder is the committed one.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rtlab::grader {

// The stubs at git's HEAD: repository path -> contents; empty outside a git checkout, where
// no commit tells a stub from a student's file.
std::map<std::string, std::string> committedStubs(const std::string& sourceDir);

// Repository path ("assignments/a0_intersect/ray_box.cpp") -> contents. Throws rtlab::Error
// when the stubs cannot be read, or when one of `folders` (of assignments/) has none: an
// assignment added to the tree but not yet committed.
std::map<std::string, std::string> pristineStubs(const std::string& sourceDir, const std::vector<std::string>& folders = {});

}  // namespace rtlab::grader
