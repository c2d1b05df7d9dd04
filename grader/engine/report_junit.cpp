// JUnit XML, valid against the junit-10 schema (grader/schemas/junit-10.xsd, checked by the
// junit_schema test): one testsuite per assignment. "Not started" is a failure, not a skip, so
// a CI dashboard never shows an untouched stub as green. Points go into each testcase's
// system-out and the suite's properties, the only places the schema leaves for them.
#include "framework/core/error.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/markup_escape.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace rtlab::grader {
namespace {

// xs:decimal allows no exponent, so neither ostream's default nor %g will do.
std::string seconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", s >= 0 ? s : 0.0);
    return buffer;
}

std::string points(double p) {
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, p, std::chars_format::fixed);
    return error == std::errc() ? std::string(buffer, end) : "0";
}

struct Suite {
    std::vector<const TestResult*> tests;
    size_t failures = 0;
    double seconds = 0.0, score = 0.0, maxScore = 0.0;
};

void writeTestcase(std::ostringstream& xml, const TestResult& t) {
    xml << "    <testcase name=\"" << escapeMarkup(t.name) << "\" classname=\"" << escapeMarkup(t.assignment) << "\" time=\""
        << seconds(t.seconds) << "\">\n";
    if (t.status != TestStatus::Passed)
        xml << "      <failure type=\"" << testStatusName(t.status) << "\" message=\"" << escapeMarkup(t.reason) << "\">"
            << escapeMarkup(testOutput(t)) << "</failure>\n";
    xml << "      <system-out>" << points(t.score) << " of " << points(t.maxScore) << " points</system-out>\n";
    xml << "    </testcase>\n";
}

}  // namespace

void writeJunitReport(const GradingReport& untrusted, const std::string& path) {
    const GradingReport report = displaySafe(untrusted);
    std::map<std::string, Suite> suites;
    size_t failures = 0;
    for (const TestResult& t : report.tests) {
        Suite& suite = suites[t.assignment];
        suite.tests.push_back(&t);
        suite.failures += t.status != TestStatus::Passed;
        suite.seconds += t.seconds;
        suite.score += t.score;
        suite.maxScore += t.maxScore;
        failures += t.status != TestStatus::Passed;
    }
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"rtlab grader\" tests=\"" << report.tests.size()
        << "\" failures=\"" << failures << "\" errors=\"0\" time=\"" << seconds(report.seconds) << "\">\n";
    bool first = true;
    for (const auto& [assignment, suite] : suites) {
        xml << "  <testsuite name=\"" << escapeMarkup(assignment) << "\" tests=\"" << suite.tests.size() << "\" failures=\""
            << suite.failures << "\" errors=\"0\" skipped=\"0\" time=\"" << seconds(suite.seconds) << "\">\n";
        xml << "    <properties>\n      <property name=\"implementation\" value=\"" << escapeMarkup(report.implementation)
            << "\"/>\n      <property name=\"seed\" value=\"" << report.seed << "\"/>\n      <property name=\"score\" value=\""
            << points(suite.score) << "\"/>\n      <property name=\"max_score\" value=\"" << points(suite.maxScore) << "\"/>\n"
            << "    </properties>\n";
        for (const TestResult* t : suite.tests) writeTestcase(xml, *t);
        // What student code printed belongs to the whole run; the schema has no place for it
        // above the suites, so the first suite carries it.
        if (first && !report.studentOutput.empty())
            xml << "    <system-out>" << escapeMarkup(report.studentOutput) << "</system-out>\n";
        first = false;
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
