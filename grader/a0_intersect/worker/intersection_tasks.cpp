// a0's functions on the grader's cases: one answer per query, in order.
#include "framework/interface/a0_intersect.h"
#include "grader/a0_intersect/wire/intersection_inputs.h"
#include "grader/worker/worker_tasks.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxQueries = uint64_t(1) << 24;
constexpr uint64_t kMaxBoxes = 64;

void putBoxAnswer(const Bounds3f& box, const Ray& ray, ByteWriter& output) {
    float enter = std::numeric_limits<float>::quiet_NaN();
    bool hit = intersectBox(box, RayInverse(ray), ray.tMin, ray.tMax, &enter);
    output.put<uint8_t>(hit);
    output.put<float>(enter);
}

void runBoxQueries(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const BoxQuery& q : input.getVector<BoxQuery>(kMaxQueries)) putBoxAnswer(q.box, q.ray, output);
}

void runRaysAgainstBoxes(ByteReader& input, ByteWriter& output, WorkerState&) {
    const std::vector<Bounds3f> boxes = input.getVector<Bounds3f>(kMaxBoxes);
    for (const Ray& ray : input.getVector<Ray>(kMaxQueries / std::max<size_t>(1, boxes.size())))
        for (const Bounds3f& box : boxes) putBoxAnswer(box, ray, output);
}

void runTriangleQueries(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const TriangleQuery& q : input.getVector<TriangleQuery>(kMaxQueries)) {
        TriangleHit hit{};
        bool found = intersectTriangle(q.ray, q.ray.tMax, q.p0, q.p1, q.p2, &hit);
        output.put<uint8_t>(found);
        output.put<float>(hit.t);
    }
}

// The nearest hit over a whole mesh, shrinking tMax as a traversal would.
void runClosestTriangle(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto triangles = input.getVector<std::array<Vec3, 3>>(kMaxQueries);
    for (const Ray& ray : input.getVector<Ray>(kMaxQueries)) {
        float closest = ray.tMax;
        for (const auto& v : triangles) {
            TriangleHit hit{};
            if (intersectTriangle(ray, closest, v[0], v[1], v[2], &hit)) closest = hit.t;
        }
        output.put<float>(closest);
    }
}

void runSphereQueries(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const SphereQuery& q : input.getVector<SphereQuery>(kMaxQueries)) {
        float t = std::numeric_limits<float>::quiet_NaN();
        bool hit = intersectSphere(q.ray, q.ray.tMax, q.centre, q.radius, &t);
        output.put<uint8_t>(hit);
        output.put<float>(t);
    }
}

const TaskRegistration registration{{kTaskBox, runBoxQueries},
                                    {kTaskRaysAgainstBoxes, runRaysAgainstBoxes},
                                    {kTaskTriangle, runTriangleQueries},
                                    {kTaskClosestTriangle, runClosestTriangle},
                                    {kTaskSphere, runSphereQueries}};

}  // namespace
}  // namespace rtlab::grader::worker
