// Reference values the grader compares against but cannot compute without the reference
// solution (docs/grading.md, "Regenerating references"): the cost of the reference structure
// (a BVH's SAH cost) and the reference traversal's work per ray, per scene and structure
// (build configuration). They are written by `rtlab-solution grade --write-reference` into
// grader/reference/structures.json, with the SHA-256 of each scene's geometry, and
// grader/reference/manifest.json holds the SHA-256 of that file, so stale or hand-edited
// values are reported instead of trusted.
#pragma once

#include "framework/scene/scene.h"

#include <map>
#include <optional>
#include <optional>
#include <string>

namespace rtlab::grader {

struct StructureReference {
    std::string sceneSha256;
    std::optional<double> cost;       // for structures graded by a cost (SAH)
    double closestWorkPerRay = 0.0;   // node visits, cell and plane steps + primitive tests, closest hit
    double occludedWorkPerRay = 0.0;  // the same for any-hit queries
};

class ReferenceData {
public:
    // Reads directory/structures.json if present; problems (missing file, manifest mismatch) are kept
    // and reported by every test that needs a value.
    static ReferenceData load(const std::string& directory);
    // The current values, to be updated with record() and written by save().
    static ReferenceData forWriting(const std::string& directory);

    bool writing() const { return writing_; }
    // The entry for key if it exists and matches the scene; otherwise why not.
    std::optional<StructureReference> find(const std::string& key, const std::string& sceneSha256, std::string* whyNot) const;
    void record(const std::string& key, const StructureReference& value) { entries_[key] = value; }
    void save() const;

private:
    std::string directory_;
    bool writing_ = false;
    std::string problem_;
    std::map<std::string, StructureReference> entries_;
};

// SHA-256 of the geometry the grader builds over (positions, indices, spheres).
std::string sceneGeometrySha256(const Scene& scene);

}  // namespace rtlab::grader
