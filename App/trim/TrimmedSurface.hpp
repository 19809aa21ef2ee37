#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Cylinder.hpp"
#include "trim/TrimLoop.hpp"

namespace nurbslod {

// A B-rep face as the tessellator sees it: a NURBS surface, its trimming loops, and whether
// the face's normal is opposite to du x dv.
struct TrimmedSurface {
    int faceIndex = 0;  // 1-based, FreeCAD's shape.Faces order (TopExp::MapShapes)
    BSplineSurface surface;
    std::vector<TrimLoop> loops;
    bool reversed = false;
    std::string error;  // set when the face could not be imported; the face is then skipped
    // set when the face is meshed but its input is not what OpenCASCADE would make of it (a
    // hole wound like the outer wire): the user is told, and a judge may disagree with its mesh
    std::string warning;
    // The circular cylinder the surface is, where the file gave the face as one (its NURBS form
    // is the same surface): the tessellator may then triangulate the face in its unrolled plane.
    std::optional<Cylinder> cylinder;
};

}  // namespace nurbslod
