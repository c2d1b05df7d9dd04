// JUnit XML: one testsuite per assignment. "Not started" is a failure, not a skip, so a CI
// dashboard never shows an untouched stub as green.
#include "framework/core/error.h"
#include "grader/grading_report.h"
#include "grader/markup_escape.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace rtlab::grader {

void writeJunitReport(const GradingReport& report, const std::string& path) {
    std::map<std::string, std::vector<const TestResult*>> suites;
    for (const TestResult& t : report.tests) suites[t.assignment].push_back(&t);
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"rtlab grader\" time=\"" << report.seconds << "\">\n";
    for (const auto& [assignment, tests] : suites) {
        size_t failures = 0;
        for (const TestResult* t : tests) failures += t->status != TestStatus::Passed;
        xml << "  <testsuite name=\"" << escapeMarkup(assignment) << "\" tests=\"" << tests.size() << "\" failures=\"" << failures << "\">\n";
        for (const TestResult* t : tests) {
            xml << "    <testcase classname=\"" << escapeMarkup(assignment) << "\" name=\"" << escapeMarkup(t->name) << "\" time=\""
                << t->seconds << "\">\n";
            xml << "      <properties><property name=\"score\" value=\"" << t->score << "\"/><property name=\"max_score\" value=\""
                << t->maxScore << "\"/></properties>\n";
            if (t->status != TestStatus::Passed)
                xml << "      <failure type=\"" << testStatusName(t->status) << "\" message=\"" << escapeMarkup(t->reason) << "\">"
                    << escapeMarkup(testOutput(*t)) << "</failure>\n";
            xml << "    </testcase>\n";
        }
        xml << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << xml.str();
    if (!out) throw Error(path + ": cannot write the JUnit report");
}

}  // namespace rtlab::grader
