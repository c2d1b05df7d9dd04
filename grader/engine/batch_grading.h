// Grading a folder of submissions (docs/grading.md, "Grading a batch"): each submission in a
// child process of this executable (`grade --submission DIR --json FILE --quiet`), never in
// this process, under a hard wall-clock cap that nothing the child prints extends; --jobs of
// them at a time; one JSON report per submission, written whatever happened to it, so one
// broken folder costs only its own row. A shard K/N takes every N-th folder, so any engine
// (GNU parallel, a Slurm job array) can fan the work out and `rtlab grade merge` join it.
#pragma once

#include "grader/engine/rubric.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct Shard {
    int index = 1;  // 1..count
    int count = 1;
    // "K/N" with 1 <= K <= N; throws rtlab::Error for anything else.
    static Shard parse(const std::string& text);
    bool holds(size_t position) const { return position % size_t(count) == size_t(index - 1); }
};

struct BatchOptions {
    std::string submissionsDir;
    std::string reportsDir;     // <reportsDir>/<folder name>.json
    std::string csvPath;        // empty: no CSV (a shard of a fan-out)
    std::string workDir;        // a folder per submission below it
    Rubric rubric;              // applied to every row; its precision rounds the CSV
    std::string executable;     // the grader to run as the child (this executable)
    // Passed to every child after `grade --submission DIR`: seed, limits, root, models, ...
    std::vector<std::string> gradeArguments;
    int jobs = 2;
    Shard shard;
    bool force = false;                  // re-grade folders whose report exists
    double secondsPerSubmission = 900;   // the hard cap per child
};

struct BatchSummary {
    size_t graded = 0, skipped = 0, notGraded = 0;  // notGraded: the child failed; the row says why
    std::vector<std::string> reportPaths;           // every folder of the shard, graded or skipped
};

// The folders of a batch, sorted by name: subdirectories, and symbolic links whose target is
// missing (so that they get a row saying so). Throws rtlab::Error naming an unreadable folder.
std::vector<std::string> submissionFolders(const std::string& submissionsDir);

BatchSummary gradeBatch(const BatchOptions& options);

}  // namespace rtlab::grader
