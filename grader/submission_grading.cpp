#include "grader/submission_grading.h"

#include "framework/core/error.h"
#include "grader/rubric.h"
#include "grader/submission_build.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

std::string tail(const std::string& text, size_t maxLines) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string out;
    for (size_t i = lines.size() > maxLines ? lines.size() - maxLines : 0; i < lines.size(); ++i) out += lines[i] + "\n";
    return out;
}

std::vector<std::string> splitLines(const std::string& text, size_t maxLines) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line) && lines.size() < maxLines;) lines.push_back(line);
    return lines;
}

// Runs the submission's rtlab on itself, output to logPath; returns the exit status.
int runInnerGrader(const std::vector<std::string>& arguments, const std::string& logPath) {
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = fork();
    if (pid < 0) throw Error("grader: cannot fork");
    if (pid == 0) {
        int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(log, STDOUT_FILENO);
        dup2(log, STDERR_FILENO);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

GradingReport gradeSubmission(const std::string& submissionDir, const SubmissionOptions& options) {
    auto start = std::chrono::steady_clock::now();
    const GradingOptions& g = options.grading;
    fs::create_directories(options.workDir);
    TestResult buildTest = makeResult("build", "build");
    SubmissionBuild build = buildSubmission(submissionDir, g.sourceDir, options.toolchainPath, options.workDir + "/build");

    GradingReport report;
    report.implementation = "submission " + submissionDir;
    report.seed = g.seed;
    if (!build.succeeded) {
        buildTest.reason = "the submission does not compile: " + splitLines(build.log, 1).front();
        buildTest.details = splitLines(build.log, 60);
    } else {
        std::string reportPath = options.workDir + "/report.json", logPath = options.workDir + "/grader.log";
        std::vector<std::string> arguments = {build.executable, "grade", "--root", g.sourceDir, "--models", g.modelsDir,
                                              "--work", options.workDir + "/work", "--seed", std::to_string(g.seed),
                                              "--json", reportPath, "--quiet", "--label", report.implementation,
                                              "--time-limit", std::to_string(g.limits.wallSeconds),
                                              "--memory-limit", std::to_string(g.limits.memoryMiB)};
        if (!g.rubricPath.empty()) arguments.insert(arguments.end(), {"--rubric", g.rubricPath});
        for (const std::string& a : g.assignments) arguments.insert(arguments.end(), {"--assignment", a});
        int status = runInnerGrader(arguments, logPath);
        std::ifstream logFile(logPath);
        std::string log((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
        if (status != 0 || !fs::exists(reportPath)) {
            buildTest.reason = "the submission's grader stopped with status " + std::to_string(status) + ": " + tail(log, 1);
            buildTest.details = splitLines(tail(log, 40), 40);
        } else {
            report = readJsonReport(reportPath);
            buildTest.status = TestStatus::Passed;
            buildTest.fraction = 1.0;
            for (const std::string& file : build.fromSubmission) buildTest.details.push_back("from the submission: " + file);
            for (const std::string& line : splitLines(build.log, 40)) buildTest.details.push_back(line);
        }
    }
    report.tests.insert(report.tests.begin(), buildTest);
    Rubric::load(g.rubricPath.empty() ? g.sourceDir + "/grader/rubric.json" : g.rubricPath).apply(report.tests);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

size_t gradeSubmissions(const std::string& submissionsDir, const SubmissionOptions& options, int jobs, const std::string& csvPath,
                        const std::string& reportsDir) {
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(submissionsDir))
        if (entry.is_directory()) folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    std::vector<GradingReport> reports(folders.size());
    std::atomic<size_t> next{0};
    std::mutex printing;
    auto worker = [&] {
        for (size_t i; (i = next++) < folders.size();) {
            SubmissionOptions mine = options;
            mine.workDir = options.workDir + "/" + folders[i].filename().string();
            reports[i] = gradeSubmission(folders[i].string(), mine);
            fs::create_directories(reportsDir);
            writeJsonReport(reports[i], reportsDir + "/" + folders[i].filename().string() + ".json");
            std::lock_guard lock(printing);
            std::cerr << folders[i].filename().string() << ": " << reports[i].score() << " / " << reports[i].maxScore() << "\n";
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < std::max(1, jobs); ++j) threads.emplace_back(worker);
    for (std::thread& t : threads) t.join();

    // Columns: every test any submission has, in first-seen order.
    std::vector<std::string> columns;
    std::set<std::string> seen;
    for (const GradingReport& r : reports)
        for (const TestResult& t : r.tests)
            if (seen.insert(t.name).second) columns.push_back(t.name);
    auto csvField = [](const std::string& s) {
        std::string q = "\"";
        for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    std::ofstream csv(csvPath);
    csv << "submission,score,max_score";
    for (const std::string& c : columns) csv << "," << csvField(c);
    csv << "\n";
    for (size_t i = 0; i < folders.size(); ++i) {
        csv << csvField(folders[i].filename().string()) << "," << reports[i].score() << "," << reports[i].maxScore();
        for (const std::string& c : columns) {
            auto it = std::find_if(reports[i].tests.begin(), reports[i].tests.end(), [&](const TestResult& t) { return t.name == c; });
            csv << ",";
            if (it != reports[i].tests.end()) csv << it->score;
        }
        csv << "\n";
    }
    if (!csv) throw Error(csvPath + ": cannot write the CSV");
    return folders.size();
}

}  // namespace rtlab::grader
