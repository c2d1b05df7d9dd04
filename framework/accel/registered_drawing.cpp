// A structure's drawing looked up by its --accel name in the accelerator registry. Apart from
// structure_drawing.cpp: the registry names every accelerator, and they call the assignments'
// code, so whatever links this links the assignments; the drawings themselves do not.
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/structure_drawing.h"

namespace rtlab {

StructureDrawer structureDrawer(const std::string& acceleratorName) {
    const AcceleratorType& type = acceleratorTypeOf(acceleratorName);
    return type.draw ? type.draw : drawLevels;
}

StructureDrawing drawStructure(const std::string& acceleratorName, const StructureView& view, const NodeMask& drawn) {
    return structureDrawer(acceleratorName)(view, drawn);
}

}  // namespace rtlab
