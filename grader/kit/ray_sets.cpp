#include "grader/kit/ray_sets.h"

#include "framework/core/pcg32.h"

#include <cmath>
#include <map>

namespace rtlab::grader {

const char* rayKindName(RayKind kind) {
    switch (kind) {
    case RayKind::Random: return "random";
    case RayKind::AxisAligned: return "axis-aligned";
    case RayKind::Edge: return "through an edge";
    case RayKind::Vertex: return "through a vertex";
    case RayKind::Grazing: return "grazing";
    case RayKind::Inside: return "from inside";
    }
    return "?";
}

namespace {

class RayFactory {
public:
    RayFactory(const TestScene& scene, uint64_t seed) : scene_(scene), rng_(seed, 11) {
        bounds_ = scene.scene.bounds();
        centre_ = bounds_.centre();
        extent_ = glm::length(bounds_.diagonal());
        const auto& indices = scene.scene.triangles.indices;
        for (uint32_t t = 0; t < indices.size(); ++t)
            for (int e = 0; e < 3; ++e) {
                auto key = std::minmax(indices[t][e], indices[t][(e + 1) % 3]);
                edges_[key].push_back(t);
            }
    }

    float uniform() { return rng_.uniform(); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * rng_.uniform(); }
    uint32_t below(uint32_t n) { return n == 0 ? 0 : rng_.next() % n; }

    Vec3 pointInBounds(float grow) {
        Vec3 d = bounds_.diagonal() * grow;
        Vec3 lo = centre_ - 0.5f * d;
        return lo + Vec3(uniform(), uniform(), uniform()) * d;
    }
    Vec3 unitVector() {
        float z = uniform(-1, 1), phi = uniform(0, 6.2831853f), r = std::sqrt(std::max(0.0f, 1 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    Vec3 outsideOrigin() { return centre_ + extent_ * (1.0f + uniform()) * unitVector(); }

    void add(RayKind kind, const Vec3& origin, const Vec3& direction, bool mustHit) {
        Ray ray;
        ray.origin = origin;
        ray.direction = direction;
        set_.rays.push_back(ray);
        set_.kinds.push_back(kind);
        set_.mustHit.push_back(mustHit ? 1 : 0);
    }

    void random() { add(RayKind::Random, pointInBounds(1.5f), pointInBounds(1.0f) - pointInBounds(1.5f), false); }

    // Along an axis, in the planes of a vertex: origins on the slab planes of leaf boxes, and
    // +0 / -0 in the other components.
    void axisAligned() {
        const Scene& s = scene_.scene;
        if (s.triangleCount() == 0) return random();
        Vec3 v = s.triangleVertices(below(s.triangleCount()))[below(3)];
        int axis = static_cast<int>(below(3));
        bool negative = below(2) == 1;
        Vec3 origin = v, direction(below(2) ? -0.0f : 0.0f, below(2) ? -0.0f : 0.0f, below(2) ? -0.0f : 0.0f);
        origin[axis] = negative ? bounds_.upper[axis] + 1.0f : bounds_.lower[axis] - 1.0f;
        direction[axis] = negative ? -1.0f : 1.0f;
        add(RayKind::AxisAligned, origin, direction, false);
    }

    void edge() {
        const Scene& s = scene_.scene;
        if (s.triangleCount() == 0) return random();
        uint32_t t = below(s.triangleCount());
        int e = static_cast<int>(below(3));
        const auto& idx = s.triangles.indices[t];
        uint32_t ia = idx[e], ib = idx[(e + 1) % 3];
        Vec3 a = s.triangles.positions[ia], b = s.triangles.positions[ib];
        Vec3 target = a + uniform(0.001f, 0.999f) * (b - a);
        Vec3 origin = scene_.closed ? scene_.inside : outsideOrigin();
        add(RayKind::Edge, origin, target - origin, scene_.closed || crossesManifoldEdge(origin, ia, ib));
    }

    void vertex() {
        const Scene& s = scene_.scene;
        if (s.triangleCount() == 0) return random();
        Vec3 v = s.triangleVertices(below(s.triangleCount()))[below(3)];
        Vec3 origin = scene_.closed ? scene_.inside : outsideOrigin();
        add(RayKind::Vertex, origin, v - origin, scene_.closed);
    }

    // Nearly in the plane of a triangle, through a point inside it.
    void grazing() {
        const Scene& s = scene_.scene;
        if (s.triangleCount() == 0) return random();
        auto v = s.triangleVertices(below(s.triangleCount()));
        float b1 = uniform(0.05f, 0.45f), b2 = uniform(0.05f, 0.45f);
        Vec3 p = (1 - b1 - b2) * v[0] + b1 * v[1] + b2 * v[2];
        Vec3 along = v[1] - v[0];
        Vec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
        float n = glm::length(normal);
        if (!(n > 0)) return random();
        Vec3 d = along + (below(2) ? 1e-3f : -1e-3f) * glm::length(along) * normal / n;
        add(RayKind::Grazing, p - 2.0f * d, d, false);
    }

    void inside() {
        Vec3 origin = scene_.closed ? scene_.inside + 0.05f * Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))
                                    : pointInBounds(0.9f);
        add(RayKind::Inside, origin, unitVector(), scene_.closed);
    }

    RaySet take() { return std::move(set_); }

private:
    // A ray through the edge (a, b) certainly meets the surface when exactly two triangles
    // share the edge and their third vertices lie on opposite sides of the plane through the
    // origin and the edge (otherwise the edge is a silhouette the ray may just touch).
    bool crossesManifoldEdge(const Vec3& origin, uint32_t ia, uint32_t ib) const {
        auto it = edges_.find(std::minmax(ia, ib));
        if (it == edges_.end() || it->second.size() != 2) return false;
        const Scene& s = scene_.scene;
        DVec3 o(origin), a(s.triangles.positions[ia]), b(s.triangles.positions[ib]);
        DVec3 normal = glm::cross(a - o, b - o);
        double side[2];
        for (int k = 0; k < 2; ++k) {
            const auto& idx = s.triangles.indices[it->second[k]];
            uint32_t third = idx[0] != ia && idx[0] != ib ? idx[0] : (idx[1] != ia && idx[1] != ib ? idx[1] : idx[2]);
            side[k] = glm::dot(normal, DVec3(s.triangles.positions[third]) - o);
        }
        return side[0] * side[1] < 0;
    }

    const TestScene& scene_;
    Pcg32 rng_;
    Bounds3f bounds_;
    Vec3 centre_;
    float extent_ = 1.0f;
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges_;
    RaySet set_;
};

}  // namespace

RaySet makeRaySet(const TestScene& scene, int count, uint64_t seed) {
    RayFactory factory(scene, seed);
    for (int i = 0; i < count; ++i) {
        switch (i % 20) {
        case 0: case 1: case 2: case 3: case 4: case 5: factory.random(); break;
        case 6: case 7: factory.axisAligned(); break;
        case 8: case 9: case 10: case 11: factory.edge(); break;
        case 12: case 13: factory.vertex(); break;
        case 14: case 15: case 16: factory.grazing(); break;
        default: factory.inside(); break;
        }
    }
    return factory.take();
}

std::vector<Ray> withRandomTMax(const std::vector<Ray>& rays, const Scene& scene, uint64_t seed) {
    Pcg32 rng(seed, 13);
    float extent = glm::length(scene.bounds().diagonal());
    std::vector<Ray> cut = rays;
    for (Ray& ray : cut) {
        float length = glm::length(ray.direction);
        if (length > 0) ray.tMax = 1.5f * extent * rng.uniform() / length;
    }
    return cut;
}

}  // namespace rtlab::grader
