#pragma once

#include <optional>
#include <vector>

#include "geometry/BSplineCurve2d.hpp"

namespace nurbslod {

// One use of a B-rep edge by a face: the edge's curve in the face's parameter plane (pcurve)
// over the edge parameter range [first, last]. The edge parameter is the one the 3D edge
// curve and every pcurve of the edge share, so an edge discretised once in t is shared.
struct TrimCurve {
    int edge = -1;          // index into Model::edges
    BSplineCurve2d pcurve;  // in the surface's (u, v) plane
    double first = 0, last = 1;
    bool reversed = false;     // the loop runs from `last` to `first`
    bool seam = false;         // the edge bounds the face on both sides (a closed surface)
    bool degenerated = false;  // the edge is a single 3D point (a pole of a sphere or cone)
    // The file's curve where the importer straightened it within its edge's tolerance
    // (straightenNearIsoparametric): a point the edge's faces share is held near it, as near as
    // the B-rep places the edge.
    std::optional<BSplineCurve2d> beforeStraightening;
};

// A closed chain of trimming curves in the order the face's wire runs. Orientation in the
// (u, v) plane is not trusted: the tessellator fills by the even-odd rule.
struct TrimLoop {
    std::vector<TrimCurve> curves;
    bool outer = false;
};

}  // namespace nurbslod
