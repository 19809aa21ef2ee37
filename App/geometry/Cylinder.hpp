#pragma once

#include "geometry/Point.hpp"

namespace nurbslod {

// A circular cylinder: the points at `radius` from the line through `origin` along `axis` (a
// unit vector). What a B-rep face's surface was in the file before it became a NURBS: the
// rational form says the same surface, but not that it is developable, which lets a face on it
// be triangulated in its unrolled plane (CylinderDevelopment).
struct Cylinder {
    Point3 origin = Point3::Zero();
    Vector3 axis = Vector3::UnitZ();
    double radius = 0;
};

}  // namespace nurbslod
