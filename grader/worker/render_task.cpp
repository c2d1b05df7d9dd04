// A whole render with the student's a0 intersections and the structure the grader names (a1's
// median BVH, a3's grid), for the image tests.
#include "framework/accel/accelerator.h"
#include "framework/render/renderer.h"
#include "grader/wire/scene_codec.h"
#include "grader/wire/task_inputs.h"
#include "grader/worker/worker_tasks.h"

#include <algorithm>
#include <span>

namespace rtlab::grader::worker {
namespace {

void runRender(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto request = input.get<RenderRequest>();
    if (request.camera >= state.scene.cameras.size() || request.width <= 0 || request.height <= 0 || request.width > 8192 ||
        request.height > 8192)
        throw WireError("a render request out of range");
    if (std::find(request.accelerator, request.accelerator + sizeof request.accelerator, '\0') ==
        request.accelerator + sizeof request.accelerator)
        throw WireError("an accelerator name without its end");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(AcceleratorSpec{request.accelerator});
    accelerator->build(*state.primitives);
    RenderSettings settings;
    settings.width = request.width;
    settings.height = request.height;
    settings.threads = request.threads;
    settings.progress = false;
    RenderResult result = Renderer(state.scene, state.scene.cameras[request.camera], *accelerator).render(settings);
    output.put<int32_t>(result.colour.width);
    output.put<int32_t>(result.colour.height);
    output.put<int32_t>(result.colour.channels);
    output.putVector(std::span<const float>(result.colour.pixels));
}

const TaskRegistration registration{{kTaskRender, runRender}};

}  // namespace

}  // namespace rtlab::grader::worker
