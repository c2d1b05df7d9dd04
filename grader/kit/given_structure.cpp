#include "grader/kit/given_structure.h"

#include "framework/core/pcg32.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtlab::grader {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where the segment (t0, t1) of the ray, in double, meets the closed box grown by `grow` (a
// negative grow shrinks it): the parameter range, empty when t0 > t1.
std::pair<double, double> segmentInBox(const Bounds3f& box, double grow, const Ray& ray, double t0, double t1) {
    for (int a = 0; a < 3; ++a) {
        double lo = double(box.lower[a]) - grow, hi = double(box.upper[a]) + grow;
        double o = ray.origin[a], d = ray.direction[a];
        if (d == 0.0) {
            if (o < lo || o > hi) return {kInf, -kInf};
            continue;
        }
        double n = (lo - o) / d, f = (hi - o) / d;
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
    }
    return {t0, t1};
}

std::string formatT(double t) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.9g", t);
    return buffer;
}

}  // namespace

void leaveOut(LeafList& leaves, uint32_t primCount, uint64_t key, bool keepLeavesFilled) {
    enum class Fate : uint8_t { Kept, Gone, OneLeaf };
    Pcg32 rng(key, 29);
    std::vector<Fate> fate(primCount);
    std::vector<uint32_t> keptLeaf(primCount);
    for (uint32_t p = 0; p < primCount; ++p) {
        uint32_t draw = rng.next() % 10;
        fate[p] = draw == 0 ? Fate::Gone : draw <= 3 ? Fate::OneLeaf : Fate::Kept;
        keptLeaf[p] = rng.next();
    }
    // The one leaf a OneLeaf primitive stays in: the keptLeaf-th of its leaves (mod their count).
    std::vector<uint32_t> seen(primCount, 0), total(primCount, 0);
    for (const auto& list : leaves.prims)
        for (uint32_t p : list) ++total[p];
    for (auto& list : leaves.prims) {
        std::vector<uint32_t> kept;
        for (uint32_t p : list) {
            bool keep = fate[p] == Fate::Kept || (fate[p] == Fate::OneLeaf && seen[p] == keptLeaf[p] % total[p]);
            ++seen[p];
            if (keep) kept.push_back(p);
        }
        if (kept.empty() && keepLeavesFilled && !list.empty()) kept.push_back(list.front());
        list = std::move(kept);
    }
}

GivenStructureJudge::GivenStructureJudge(LeafList leaves, const Scene& scene) : leaves_(std::move(leaves)), leavesOfPrim_(scene.primitiveCount()) {
    for (uint32_t leaf = 0; leaf < leaves_.prims.size(); ++leaf)
        for (uint32_t p : leaves_.prims[leaf])
            if (p < leavesOfPrim_.size()) leavesOfPrim_[p].push_back(leaf);
    double scale = 0.0;
    for (const Bounds3f& box : leaves_.boxes)
        for (int a = 0; a < 3; ++a)
            if (std::isfinite(box.lower[a]) && std::isfinite(box.upper[a]))
                scale = std::max({scale, std::abs(double(box.lower[a])), std::abs(double(box.upper[a])), double(box.upper[a]) - box.lower[a]});
    slack_ = 1e-5 * scale;
}

bool GivenStructureJudge::heldByStructure(uint32_t prim) const {
    return prim < leavesOfPrim_.size() && !leavesOfPrim_[prim].empty();
}

bool GivenStructureJudge::surelyListed(uint32_t prim, const Ray& ray, double t) const {
    for (uint32_t leaf : leavesOfPrim_[prim]) {
        auto [t0, t1] = segmentInBox(leaves_.boxes[leaf], -slack_, ray, t, t);
        if (t0 <= t1) return true;
    }
    return false;
}

std::string GivenStructureJudge::judgeClosest(HitJudge& judge, size_t index, const Ray& ray, const HitAnswer& answer) const {
    const auto& all = judge.candidates(index, ray);
    // The nearest robust hit in the segment whose point lies in a leaf that lists its primitive.
    double bound = kInf, boundTolerance = 0.0;
    uint32_t boundPrim = kNoHit;
    for (const HitJudge::Candidate& c : all)
        if (c.robust && c.t < bound && c.t - c.tolerance > ray.tMin && c.t + c.tolerance <= ray.tMax && surelyListed(c.prim, ray, c.t)) {
            bound = c.t;
            boundTolerance = c.tolerance;
            boundPrim = c.prim;
        }
    const std::string expected = std::isfinite(bound) ? "expected a hit at t=" + formatT(bound) + " or nearer (prim " + std::to_string(boundPrim) +
                                                            ", listed in the leaf that holds that point)"
                                                      : "expected a miss";
    if (answer.prim == kNoHit) return std::isfinite(bound) ? expected + ", got a miss" : "";
    const std::string got = ", got prim " + std::to_string(answer.prim) + " at t=" + formatT(answer.t);
    auto match = std::find_if(all.begin(), all.end(), [&](const HitJudge::Candidate& c) {
        return c.prim == answer.prim && std::abs(c.t - double(answer.t)) <= c.tolerance;
    });
    if (match == all.end()) return expected + got + " (that primitive is not hit there)";
    if (!(answer.t > ray.tMin && answer.t <= ray.tMax)) return "a hit must satisfy tMin < t <= tMax" + got;
    if (!heldByStructure(answer.prim)) return expected + got + ", " + kNotInStructure;
    if (double(answer.t) > bound + boundTolerance + match->tolerance) return expected + got + " (a nearer hit the structure holds was missed)";
    return "";
}

std::string GivenStructureJudge::judgeOccluded(HitJudge& judge, size_t index, const Ray& ray, bool occluded) const {
    const auto& all = judge.candidates(index, ray);
    bool justified = false, required = false, blockedInScene = false;
    for (const HitJudge::Candidate& c : all) {
        bool inSegment = c.t + c.tolerance > ray.tMin && c.t - c.tolerance <= ray.tMax;
        blockedInScene |= inSegment;
        justified |= inSegment && heldByStructure(c.prim);
        required |= c.robust && c.t - c.tolerance > ray.tMin && c.t + c.tolerance <= ray.tMax && surelyListed(c.prim, ray, c.t);
    }
    if (occluded && !justified)
        return blockedInScene ? std::string("expected not occluded, got occluded: what blocks the segment is ") + kNotInStructure
                              : "expected not occluded (nothing in the segment), got occluded";
    if (!occluded && required) return "expected occluded (a primitive listed in the leaf where it blocks the segment), got not occluded";
    return "";
}

}  // namespace rtlab::grader
