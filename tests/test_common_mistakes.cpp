// Every common mistake is a test (docs/a0-intersect.md, a1-bvh.md, a2-sah.md, a3-grid.md,
// a6-radiometry.md, "Common mistakes"): each row of those tables is a mutant of the reference
// solution in tests/mutants/mutants.json, graded by the real grader (rtlab-grader grade
// --submission), and the test the row names must fail on it, for the reason the row gives. The
// recipes the pages spell out step by step are graded the same way, transcribed literally, and
// must keep full marks.
//
// Mutants are made by text replacement in the solution files, so a solution edit that removes a
// replaced text fails here loudly instead of silently grading the unmutated reference.
#include "grader/engine/assignment_registry.h"
#include "grader/engine/grading_report.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace rtlab::grader;

namespace {

const fs::path kSource = RTLAB_SOURCE_DIR, kBinary = RTLAB_BINARY_DIR;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), (path.string() + " cannot be read"));
    return std::string(std::istreambuf_iterator<char>(in), {});
}

nlohmann::json loadMutants() { return nlohmann::json::parse(readText(kSource / "tests/mutants/mutants.json")); }

// --- The docs' tables -------------------------------------------------------------------------

struct DocsRow {
    std::string mistake, caughtBy;
};

// The cells of a Markdown table row; `\|` inside a cell is a literal bar, not a separator.
std::vector<std::string> splitCells(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (size_t i = 1; i < line.size(); ++i) {  // line[0] is the leading '|'
        if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
            cell += '|';
            ++i;
        } else if (line[i] == '|') {
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    for (std::string& c : cells) {
        c.erase(0, c.find_first_not_of(' '));
        c.erase(c.find_last_not_of(' ') + 1);
    }
    return cells;
}

// The rows of the page's "## Common mistakes" table (header and separator skipped).
std::vector<DocsRow> commonMistakes(const std::string& page) {
    std::istringstream in(readText(kSource / page));
    std::vector<DocsRow> rows;
    bool inSection = false;
    int tableLine = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) {
            inSection = line == "## Common mistakes";
            continue;
        }
        if (!inSection || line.rfind("|", 0) != 0) continue;
        if (tableLine++ < 2) continue;  // | Mistake | What you see | Caught by |, then |---|
        auto cells = splitCells(line);
        REQUIRE_MESSAGE(cells.size() == 3, (page + ": a Common mistakes row without three cells: " + line));
        rows.push_back({cells[0], cells[2]});
    }
    REQUIRE_MESSAGE(!rows.empty(), (page + " has no \"## Common mistakes\" table"));
    return rows;
}

// How a docs cell names a graded test: by its last component ("face-planes", "efficiency").
std::string shortName(const std::string& test) { return test.substr(test.rfind('/') + 1); }

// --- Submissions ------------------------------------------------------------------------------

// The solution folders an assignment's grading runs (the registry says what it builds on). The
// others stay the committed stubs (and compile quickly).
std::vector<std::string> solutionFolders(const std::string& assignment) {
    const rtlab::grader::Assignment* a = rtlab::grader::findAssignment(assignment);
    REQUIRE_MESSAGE(a, ("tests/mutants/mutants.json names assignment " + assignment + ", which the registry does not have"));
    return a->folders;
}

// Replaces `replace` by `with` in the submission's copy of a solution file. The text must occur
// exactly once: a mutant that no longer applies is an error, never a silent skip.
void applyPatch(const fs::path& submission, const nlohmann::json& patch, const std::string& entry) {
    fs::path file = submission / "assignments" / patch.at("file").get<std::string>();
    std::string text = readText(file);
    const std::string from = patch.at("replace"), to = patch.at("with");
    size_t at = text.find(from);
    std::string where = entry + ": solutions/" + patch.at("file").get<std::string>();
    REQUIRE_MESSAGE(at != std::string::npos, (where + " no longer contains the text to replace: " + from));
    REQUIRE_MESSAGE(text.find(from, at + 1) == std::string::npos, (where + " contains the text to replace more than once: " + from));
    text.replace(at, from.size(), to);
    std::ofstream(file, std::ios::binary) << text;
}

// The files whose tests call nothing else (data "independent_files": a0/slab/* call only
// intersectBox, a2/splits/sweep and a2/sweep*/ only splitSahSweep, ...): mutants of different
// such files can share one submission and one grading, each judged by its own file's tests.
struct Independence {
    std::map<std::string, std::vector<std::string>> testsOfFile;  // file -> test name prefixes

    // The file a mutant may share a submission through, or "" when it must be graded alone.
    std::string sharedFile(const nlohmann::json& entry) const {
        std::set<std::string> files;
        for (const auto& patch : entry.value("patches", nlohmann::json::array())) files.insert(patch.at("file").get<std::string>());
        const nlohmann::json own = entry.value("files", nlohmann::json::object());
        for (const auto& [target, source] : own.items()) files.insert(target);
        if (files.size() != 1 || !testsOfFile.count(*files.begin())) return "";
        return *files.begin();
    }
    bool isTestOf(const std::string& file, const std::string& test) const {
        for (const std::string& prefix : testsOfFile.at(file))
            if (test.rfind(prefix, 0) == 0) return true;
        return false;
    }
};

struct Grading {
    std::string id, assignment;
    fs::path submission, json;
    std::vector<nlohmann::json> entries;  // the mutants or recipes in this submission

    // The tests the entries are judged by, for --test; empty (every test) when a recipe must
    // earn all of its assignment's points.
    std::set<std::string> judgedTests() const {
        std::set<std::string> names;
        for (const nlohmann::json& entry : entries) {
            if (entry.value("full_marks", false)) return {};
            for (const auto& expected : entry.value("must_fail", nlohmann::json::array())) names.insert(expected.at("test").get<std::string>());
            for (const auto& name : entry.value("must_pass", nlohmann::json::array())) names.insert(name.get<std::string>());
        }
        return names;
    }
};

void addEntry(Grading& g, const nlohmann::json& entry) {
    const std::string id = entry.at("id");
    for (const auto& patch : entry.value("patches", nlohmann::json::array())) applyPatch(g.submission, patch, id);
    // A recipe's own file, written from the docs' prose, replaces the solution's.
    const nlohmann::json files = entry.value("files", nlohmann::json::object());
    for (const auto& [target, source] : files.items())
        fs::copy_file(kSource / "tests/mutants" / source.get<std::string>(), g.submission / "assignments" / target,
                      fs::copy_options::overwrite_existing);
    g.entries.push_back(entry);
}

// Lays every entry over a copy of the reference solutions: entries of independent files share a
// submission (at most one per file), the others get one each.
std::vector<Grading> assemble(const std::vector<nlohmann::json>& entries, const Independence& independence, const fs::path& work) {
    std::vector<Grading> gradings;
    std::vector<std::set<std::string>> filesTaken;  // per grading; empty set: not shared
    for (const nlohmann::json& entry : entries) {
        const std::string assignment = entry.at("assignment"), file = independence.sharedFile(entry);
        Grading* into = nullptr;
        for (size_t i = 0; i < gradings.size() && !file.empty(); ++i)
            if (gradings[i].assignment == assignment && !filesTaken[i].empty() && !filesTaken[i].count(file)) into = &gradings[i];
        if (!into) {
            Grading g;
            g.id = entry.at("id").get<std::string>() + (file.empty() ? "" : "-and-others");
            g.assignment = assignment;
            g.submission = work / "submissions" / g.id;
            g.json = work / "reports" / (g.id + ".json");
            fs::create_directories(g.submission / "assignments");
            for (const std::string& folder : solutionFolders(assignment))
                fs::copy(kSource / "solutions" / folder, g.submission / "assignments" / folder, fs::copy_options::recursive);
            gradings.push_back(std::move(g));
            filesTaken.emplace_back();
            into = &gradings.back();
        }
        if (!file.empty()) filesTaken[into - gradings.data()].insert(file);
        addEntry(*into, entry);
    }
    return gradings;
}

// Grades every submission with rtlab-grader, two at a time (the CI machines have two cores), on
// the tests its entries are judged by.
std::string testPatterns(const Grading& g) {
    std::string patterns;
    for (const std::string& name : g.judgedTests()) patterns += " --test '" + name + "'";
    return patterns;
}

// The gradings' order, one of each assignment in turn. The first grading of an assignment
// compiles what the later ones take from the grader's caches (the other assignments' stubs, the
// unchanged files); two of them at once would both compile it.
std::vector<size_t> takingTurns(const std::vector<Grading>& gradings) {
    std::vector<std::string> assignments;
    std::map<std::string, std::vector<size_t>> queues;
    for (size_t i = 0; i < gradings.size(); ++i) {
        if (!queues.count(gradings[i].assignment)) assignments.push_back(gradings[i].assignment);
        queues[gradings[i].assignment].push_back(i);
    }
    std::vector<size_t> order;
    for (size_t round = 0; order.size() < gradings.size(); ++round)
        for (const std::string& a : assignments)
            if (round < queues[a].size()) order.push_back(queues[a][round]);
    return order;
}

void gradeAll(const std::vector<Grading>& gradings, const fs::path& work) {
    fs::create_directories(work / "reports");
    const std::vector<size_t> order = takingTurns(gradings);
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t n; (n = next++) < order.size();) {
            const Grading& g = gradings[order[n]];
            // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on "'" + std::string.
            std::string command;
            for (const std::string& piece :
                 {std::string("'"), (kBinary / "rtlab-grader").string(), std::string("' grade --submission '"), g.submission.string(),
                  "' --assignment " + g.assignment + testPatterns(g) + " --json '", g.json.string(), std::string("' --quiet --root '"), kSource.string(),
                  std::string("' --models '"), (kBinary / "models").string(), std::string("' --work '"), (work / "grading" / g.id).string(),
                  std::string("' > '"), (work / "reports" / (g.id + ".log")).string(), std::string("' 2>&1")})
                command += piece;
            std::system(command.c_str());
        }
    };
    std::thread a(worker), b(worker);
    a.join();
    b.join();
}

// All results of a test name (a test over several scenes may report once per scene).
std::vector<const TestResult*> resultsNamed(const GradingReport& report, const std::string& name) {
    std::vector<const TestResult*> found;
    for (const TestResult& t : report.tests)
        if (t.name == name) found.push_back(&t);
    return found;
}

std::vector<std::string> asList(const nlohmann::json& value) {
    if (value.is_string()) return {value.get<std::string>()};
    return value.get<std::vector<std::string>>();
}

void checkEntry(const Grading& g, const GradingReport& report, const nlohmann::json& entry, const Independence& independence) {
    const std::string id = entry.at("id");
    CAPTURE(id);
    const std::string file = g.entries.size() > 1 ? independence.sharedFile(entry) : "";
    for (const auto& expected : entry.value("must_fail", nlohmann::json::array())) {
        std::string name = expected.at("test");
        CAPTURE(name);
        // In a shared submission only this file's tests may judge it (they call nothing else).
        if (!file.empty()) CHECK_MESSAGE(independence.isTestOf(file, name), (id + ": " + name + " is not a test of " + file));
        auto found = resultsNamed(report, name);
        REQUIRE_MESSAGE(!found.empty(), (id + ": the report has no test " + name));
        std::string output;
        bool failed = false;
        for (const TestResult* t : found) {
            failed |= t->status == TestStatus::Failed;
            output += testOutput(*t) + "\n";
        }
        CAPTURE(output);
        CHECK_MESSAGE(failed, (id + ": " + name + " does not catch this mistake"));
        // The failure must point at the mistake: a case id, a property, a crash in the function.
        bool mentioned = false;
        for (const std::string& text : asList(expected.at("mentions"))) mentioned |= output.find(text) != std::string::npos;
        CHECK_MESSAGE(mentioned, (id + ": " + name + " fails, but its reason does not mention " + expected.at("mentions").dump()));
    }
    for (const auto& name : entry.value("must_pass", nlohmann::json::array())) {
        CAPTURE(name);
        if (!file.empty()) CHECK_MESSAGE(independence.isTestOf(file, name), (id + ": " + name.get<std::string>() + " is not a test of " + file));
        auto found = resultsNamed(report, name.get<std::string>());
        REQUIRE_MESSAGE(!found.empty(), (id + ": the report has no test " + name.get<std::string>()));
        for (const TestResult* t : found) CHECK_MESSAGE(t->status == TestStatus::Passed, (id + ": " + testOutput(*t)));
    }
    // A recipe, followed literally, earns every point its file's tests give (all of its
    // assignment's when graded alone).
    if (entry.value("full_marks", false)) {
        size_t judged = 0;
        for (const TestResult& t : report.tests) {
            if (t.assignment != g.assignment || (!file.empty() && !independence.isTestOf(file, t.name))) continue;
            ++judged;
            CHECK_MESSAGE(t.status == TestStatus::Passed, (id + ": " + t.name + ": " + testOutput(t)));
        }
        CHECK(judged > 0);
    }
}

void checkVerdicts(const Grading& g, const Independence& independence) {
    CAPTURE(g.id);
    const fs::path log = g.json.parent_path() / (g.id + ".log");
    CHECK_MESSAGE(fs::exists(g.json), (g.id + ": the grader wrote no report: " + (fs::exists(log) ? readText(log) : std::string())));
    if (!fs::exists(g.json)) return;  // the other submissions are still judged
    GradingReport report = readJsonReport(g.json.string());
    auto build = resultsNamed(report, "build");
    if (!build.empty()) REQUIRE_MESSAGE(build.front()->status == TestStatus::Passed, (g.id + " does not compile: " + testOutput(*build.front())));
    for (const nlohmann::json& entry : g.entries) checkEntry(g, report, entry, independence);
}

}  // namespace

TEST_CASE("common mistakes: every row of the docs' tables has a mutant, and every mutant a row") {
    nlohmann::json data = loadMutants();
    std::set<std::string> ids;
    for (const auto& page : data.at("pages")) {
        const std::string path = page.get<std::string>();
        CAPTURE(path);
        std::vector<DocsRow> rows = commonMistakes(path);
        std::vector<int> mutantsPerRow(rows.size(), 0);
        for (const auto& m : data.at("mutants")) {
            if (m.at("page") != path) continue;
            std::string id = m.at("id"), row = m.at("row");
            CAPTURE(id);
            CHECK_MESSAGE(ids.insert(id).second, ("two mutants are called " + id));
            // `row` is a piece of the Mistake cell that names exactly one row.
            std::vector<size_t> matches;
            for (size_t r = 0; r < rows.size(); ++r)
                if (rows[r].mistake.find(row) != std::string::npos) matches.push_back(r);
            if (matches.size() != 1) {
                FAIL_CHECK((id + ": \"" + row + "\" matches " + std::to_string(matches.size()) + " rows of " + path +
                           "'s Common mistakes table, not one"));
                continue;
            }
            ++mutantsPerRow[matches.front()];
            // The Caught-by column names each test that really catches it, by name or case id;
            // a mistake no test catches yet says so (and its entry checks that it still passes).
            const std::string& caughtBy = rows[matches.front()].caughtBy;
            if (m.contains("not_caught")) {
                CHECK_MESSAGE(caughtBy.find("not caught") != std::string::npos,
                              (id + ": no test catches it, but the Caught-by column says \"" + caughtBy + "\""));
                CHECK_MESSAGE(!m.value("must_pass", nlohmann::json::array()).empty(), (id + ": name the tests that miss it in must_pass"));
                continue;
            }
            for (const auto& expected : m.at("must_fail")) {
                std::string test = expected.at("test");
                bool named = caughtBy.find(shortName(test)) != std::string::npos;
                for (const std::string& text : asList(expected.at("mentions"))) named |= caughtBy.find(text) != std::string::npos;
                CHECK_MESSAGE(named, (id + ": the Caught-by column \"" + caughtBy + "\" does not name " + test));
            }
            CHECK_MESSAGE(!m.at("must_fail").empty(), (id + ": a mutant no test must catch"));
        }
        for (size_t r = 0; r < rows.size(); ++r)
            CHECK_MESSAGE(mutantsPerRow[r] > 0, (path + ": the common mistake \"" + rows[r].mistake + "\" has no mutant in tests/mutants/mutants.json"));
    }
    for (const auto& recipe : data.at("recipes")) {
        CAPTURE(recipe.at("id").get<std::string>());
        CHECK(recipe.value("full_marks", false));
        std::string page = readText(kSource / recipe.at("page").get<std::string>());
        std::string section = recipe.at("section");
        CHECK_MESSAGE(page.find("\n" + section + "\n") != std::string::npos, (recipe.at("page").get<std::string>() + " has no section " + section));
    }
}

TEST_CASE("common mistakes: the grader catches every mutant, and every recipe keeps full marks") {
    nlohmann::json data = loadMutants();
    const fs::path work = fs::temp_directory_path() / ("rtlab-mutants-" + std::to_string(::getpid()));
    fs::remove_all(work);
    Independence independence;
    for (const auto& [file, prefixes] : data.at("independent_files").items())
        independence.testsOfFile[file] = prefixes.get<std::vector<std::string>>();
    std::vector<nlohmann::json> entries;
    for (const char* list : {"mutants", "recipes"})
        for (const auto& entry : data.at(list)) entries.push_back(entry);
    std::vector<Grading> gradings = assemble(entries, independence, work);
    gradeAll(gradings, work);
    for (const Grading& g : gradings) checkVerdicts(g, independence);
    // The failures above quote the reports; RTLAB_KEEP_MUTANTS=1 keeps the submissions and logs.
    if (!std::getenv("RTLAB_KEEP_MUTANTS")) fs::remove_all(work);
}
