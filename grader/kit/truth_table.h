// The truth tables of a0 and a3-a6: a list of cases, each a call the worker makes on the student's
// function and what the pinned rule says it returns. One phase sends every case's call (after
// what the calls share); the grader reads the answers back in the same order and judges each,
// and CaseTally turns the verdicts into the test's fraction, reason and detail lines.
#pragma once

#include "framework/core/bounds.h"
#include "grader/engine/test_group.h"
#include "grader/engine/test_result.h"
#include "grader/wire/wire_format.h"

#include <initializer_list>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rtlab::grader {

// "(x, y, z)" with every float's shortest exact digits (9 significant).
std::string describeVec(const Vec3& v);
// "[(x, y, z), (x, y, z)]".
std::string describeBox(const Bounds3f& box);
// "expected <expected>, got <got>".
std::string expectedGot(const std::string& expected, const std::string& got);

// One case of a truth table: what it checks, the call the worker makes, the answer the rule gives.
template <typename Call, typename Answer>
struct TableCase {
    std::string id;
    Call call;
    Answer expected;
};

// The phase that makes every case's call, in order, after `shared` (what the calls share, such
// as the grid they are made on). makeCall(case) gives the call; the default takes `case.call`.
template <typename Case, typename MakeCall>
ChildPhase tablePhase(const std::string& stub, const char* task, const std::vector<Case>& cases, MakeCall&& makeCall,
                      ByteWriter shared = ByteWriter()) {
    std::vector<decltype(makeCall(cases.front()))> calls;
    for (const Case& c : cases) calls.push_back(makeCall(c));
    shared.putVector(calls);
    return makePhase(stub, task, std::move(shared));
}

template <typename Case>
ChildPhase tablePhase(const std::string& stub, const char* task, const std::vector<Case>& cases, ByteWriter shared = ByteWriter()) {
    return tablePhase(stub, task, cases, [](const Case& c) { return c.call; }, std::move(shared));
}

// One phase's answers and the cases they answer, in the order the phase made the calls.
template <typename Case>
struct TablePart {
    const PhaseOutcome& phase;
    const std::vector<Case>& cases;
};

// Scores a test from one or more phases' answers (a test may be fed by calls made on different
// set-ups). judge(case, reader) reads one case's answer and returns its problem ("" when right;
// the detail line is "<id>: <problem>") or a CaseLine of its own. A phase that did not complete
// decides the test (not started, crashed, ...); a record that is malformed or ends early fails
// this test alone, under its own name.
template <typename Case, typename Judge>
void scoreTable(std::initializer_list<TablePart<Case>> parts, TestResult& result, Judge&& judge) {
    for (const TablePart<Case>& part : parts)
        if (failedPhaseResult(part.phase, result)) return;
    try {
        CaseTally tally(result);
        for (const TablePart<Case>& part : parts) {
            ByteReader in(part.phase.data);
            for (const Case& c : part.cases) {
                auto verdict = judge(c, in);
                if constexpr (std::is_same_v<decltype(verdict), CaseLine>) tally.record(verdict);
                else tally.record(c.id, verdict);
            }
        }
        tally.finish();
    } catch (const WireError& e) {
        result.details.clear();
        markFailed(result, std::string("sent malformed results: ") + e.what());
    }
}

template <typename Case, typename Judge>
void scoreTable(const PhaseOutcome& phase, const std::vector<Case>& cases, TestResult& result, Judge&& judge) {
    scoreTable({TablePart<Case>{phase, cases}}, result, std::forward<Judge>(judge));
}

// A group of one truth-table test: one phase of `cases` (each with its `call`), judged by judge.
template <typename Case, typename Judge>
TestGroup tableGroup(const std::string& assignment, const std::string& title, const std::string& test, const std::string& stub,
                     const char* task, std::vector<Case> list, Judge judge, ByteWriter shared = ByteWriter()) {
    auto cases = std::make_shared<const std::vector<Case>>(std::move(list));
    TestGroup group{assignment, title, {tablePhase(stub, task, *cases, std::move(shared))}, {}};
    group.score = [assignment, test, cases, judge](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(assignment, test);
        scoreTable(run.phases[0], *cases, result, judge);
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace rtlab::grader
