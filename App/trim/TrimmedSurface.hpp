#pragma once

#include <string>
#include <vector>

#include "geometry/BSplineSurface.hpp"
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
};

}  // namespace nurbslod
