#pragma once

#include <Inventor/SbLinear.h>
#include <Inventor/SbViewVolume.h>

class SoState;

namespace nurbslod::gui {

struct FaceLod;

// How large one pixel of the window is at a face, in model units (paper out-of-core-lod,
// section 4.1): epsilon_desired = pixelError * this. For a perspective camera it is
// 2 d_viewer tan(fov_y / 2) / h_window at the point of the face's box nearest to the eye; for
// an orthographic one the view height over h_window. Read from the render state once per
// frame, then asked per face.
class ViewPixelSize {
public:
    explicit ViewPixelSize(SoState* state);

    // The pixel size at the face whose coarsest level is `coarsest` (its box grown by that
    // level's tolerance, which bounds the surface), or -1 when the box is outside the view
    // frustum.
    double at(const FaceLod& coarsest) const;

private:
    SbViewVolume viewVolume_;
    SbMatrix modelMatrix_;
    int windowHeight_ = 1;
    double scale_ = 1;  // world units per model unit
    bool perspective_ = false;
    SbVec3f eye_;
};

}  // namespace nurbslod::gui
