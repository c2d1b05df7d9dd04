// A Scene on the wire between the grader and a worker: geometry, materials, lights and
// cameras, without the file it came from (the worker may not open files).
#pragma once

#include "framework/scene/scene.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader {

void writeScene(const Scene& scene, ByteWriter& out);
// Bounded by ByteReader's limits: a malformed scene is a WireError, never a huge allocation.
Scene readScene(ByteReader& in);

}  // namespace rtlab::grader
