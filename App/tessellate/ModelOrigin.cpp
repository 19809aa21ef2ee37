#include "tessellate/ModelOrigin.hpp"

namespace nurbslod {

Model withOrigin(Model model, const Vector3& origin) {
    const Vector3 shift = model.origin - origin;
    if (shift.isZero()) return model;
    for (TrimmedSurface& face : model.faces) {
        BSplineSurface& surface = face.surface;
        for (int i = 0; i < surface.countU(); ++i)
            for (int j = 0; j < surface.countV(); ++j) {
                HomogeneousPoint3& pole = surface.pole(i, j);
                pole.head<3>() += pole.w() * shift;  // P^w = (w x, w y, w z, w)
            }
        if (face.cylinder) face.cylinder->origin += shift;
    }
    for (ModelVertex& vertex : model.vertices) vertex.point += shift;
    model.origin = origin;
    return model;
}

}  // namespace nurbslod
