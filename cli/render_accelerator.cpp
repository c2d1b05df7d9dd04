#include "cli/render_accelerator.h"

#include "framework/core/error.h"
#include "framework/core/untrusted_text.h"

namespace rtlab::cli {

std::unique_ptr<Accelerator> buildRenderAccelerator(AcceleratorSpec& spec, bool specGiven, const PrimitiveSet& primitives,
                                                    const AcceleratorFactory& make, std::ostream& notes) {
    std::unique_ptr<Accelerator> accelerator = make(spec);
    try {
        accelerator->build(primitives);
        return accelerator;
    } catch (const NotImplemented& e) {
        // Only an a2 stub has a way round it: the a1 builders and traversal are what the
        // fallback uses itself, and a0 is under every accelerator.
        if (specGiven || spec.name == kRenderFallbackAccelerator || e.stub.rfind("a2 ", 0) != 0) throw;
        // The stub's name comes from the student's build of the stubs: escaped like every
        // other message (framework/core/untrusted_text.h).
        notes << "rtlab: the default accelerator " << spec.name << " needs "
              << grader::escapeUntrusted(e.stub, grader::TextLayout::OneLine)
              << ", not implemented yet; rendering with --accel " << kRenderFallbackAccelerator
              << " (a1) instead\n";
    }
    spec.name = kRenderFallbackAccelerator;
    accelerator = make(spec);
    accelerator->build(primitives);
    return accelerator;
}

}  // namespace rtlab::cli
