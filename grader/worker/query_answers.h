// The answers of a query phase, whatever the structure: one RawQuery per ray, the traversal's
// result with the framework's counters beside it (feedback only).
#pragma once

#include "framework/interface/traversal.h"
#include "grader/wire/wire_format.h"
#include "grader/wire/task_inputs.h"

#include <algorithm>
#include <vector>

namespace rtlab::grader::worker {

// What a query phase asks after its structure (if it brings one): u8 QueryKind, [Ray].
struct QueryRequest {
    QueryKind kind;
    std::vector<Ray> rays;
};

inline QueryRequest readQueryRequest(ByteReader& input) {
    auto kind = static_cast<QueryKind>(input.get<uint8_t>());
    if (kind != QueryKind::Closest && kind != QueryKind::Occluded && kind != QueryKind::Recursive) throw WireError("bad query kind");
    return {kind, input.getVector<Ray>(uint64_t(1) << 24)};
}

// Occluded queries answer prim = 1 or 0; closest-hit ones the primitive (kNoHit on a miss) and
// t. `occludes(traversal)` and `closest(traversal, hit)` call the student's traversal.
template <typename Occludes, typename Closest>
std::vector<RawQuery> answerRays(const PrimitiveSet& primitives, const std::vector<Ray>& rays, bool occluded,
                                 Occludes&& occludes, Closest&& closest) {
    std::vector<RawQuery> answers;
    answers.reserve(rays.size());
    for (const Ray& ray : rays) {
        TraversalStats stats;
        Traversal traversal(primitives, ray, stats);
        RawQuery answer{kNoHit, 0.0f, 0, 0};
        if (occluded) {
            answer.prim = occludes(traversal) ? 1 : 0;
        } else {
            Hit hit;
            hit.t = ray.tMax;
            answer.prim = closest(traversal, hit) ? hit.prim : kNoHit;
            answer.t = hit.t;
        }
        // Box tests, cell and plane steps together: a structure's work besides its primitive tests.
        answer.nodeVisits = static_cast<uint32_t>(stats.steps());
        answer.primitiveTests = static_cast<uint32_t>(stats.primitiveTests);
        answers.push_back(answer);
    }
    return answers;
}

// A visit-order phase's answer: per ray, the list the closest-hit traversal `closest(traversal,
// hit)` keeps while `listIn(traversal, &list)` points it there (the primitives it tests, the
// leaves it enters), as u32 n then n u32, cut at maxListed.
template <typename ListIn, typename Closest>
void writeListsPerRay(const PrimitiveSet& primitives, const std::vector<Ray>& rays, uint32_t maxListed, ByteWriter& output,
                      ListIn&& listIn, Closest&& closest) {
    std::vector<uint32_t> list;
    for (const Ray& ray : rays) {
        TraversalStats stats;
        Traversal traversal(primitives, ray, stats);
        list.clear();
        listIn(traversal, &list);
        Hit hit;
        hit.t = ray.tMax;
        closest(traversal, hit);
        auto n = static_cast<uint32_t>(std::min<size_t>(list.size(), maxListed));
        output.put<uint32_t>(n);
        for (uint32_t i = 0; i < n; ++i) output.put<uint32_t>(list[i]);
    }
}

}  // namespace rtlab::grader::worker
