#pragma once

#include "geometry/Point.hpp"
#include "tessellate/Model.hpp"

namespace nurbslod {

// The same model with its coordinates starting at `origin` (Model::origin): a face brought into
// another model (an edit of one face, FaceLodCache::replaceFace) takes that model's origin.
Model withOrigin(Model model, const Vector3& origin);

}  // namespace nurbslod
