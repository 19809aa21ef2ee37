#include "ViewPixelSize.hpp"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>

#include <algorithm>
#include <cmath>

#include "lod/FaceLod.hpp"

namespace nurbslod::gui {

namespace {
// The point of the box nearest to p (p itself when inside).
SbVec3f nearestPoint(const SbBox3f& box, const SbVec3f& p) {
    SbVec3f q;
    for (int k = 0; k < 3; ++k) q[k] = std::clamp(p[k], box.getMin()[k], box.getMax()[k]);
    return q;
}
}  // namespace

ViewPixelSize::ViewPixelSize(SoState* state)
    : viewVolume_(SoViewVolumeElement::get(state)), modelMatrix_(SoModelMatrixElement::get(state)) {
    const SbViewportRegion& viewport = SoViewportRegionElement::get(state);
    windowHeight_ = std::max<int>(1, viewport.getViewportSizePixels()[1]);
    // Placements are rigid in FreeCAD; a scale would change model units per world unit.
    SbVec3f unitX;
    modelMatrix_.multDirMatrix(SbVec3f(1, 0, 0), unitX);
    scale_ = unitX.length() > 0 ? unitX.length() : 1.0;
    perspective_ = viewVolume_.getProjectionType() == SbViewVolume::PERSPECTIVE;
    eye_ = viewVolume_.getProjectionPoint();
}

double ViewPixelSize::at(const FaceLod& coarsest) const {
    SbBox3f box(coarsest.boxMin[0], coarsest.boxMin[1], coarsest.boxMin[2], coarsest.boxMax[0],
                coarsest.boxMax[1], coarsest.boxMax[2]);
    const auto grow = static_cast<float>(coarsest.tolerance);
    box.extendBy(box.getMin() - SbVec3f(grow, grow, grow));
    box.extendBy(box.getMax() + SbVec3f(grow, grow, grow));
    box.transform(modelMatrix_);
    if (!viewVolume_.intersect(box)) return -1;
    const SbVec3f nearest = perspective_ ? nearestPoint(box, eye_) : box.getCenter();
    // world size of 1/h of the screen height at that depth (SbViewVolume)
    double pixel = viewVolume_.getWorldToScreenScale(nearest, 1.0f / windowHeight_);
    if (!(pixel > 0) || !std::isfinite(pixel)) {
        // The eye is inside the box: epsilon_desired would be 0. Like the paper's 1 mm floor
        // (section 4.1), take the pixel size at the near plane instead.
        const SbVec3f near =
            eye_ + viewVolume_.getProjectionDirection() * viewVolume_.getNearDist();
        pixel = viewVolume_.getWorldToScreenScale(near, 1.0f / windowHeight_);
    }
    return pixel / scale_;
}

}  // namespace nurbslod::gui
