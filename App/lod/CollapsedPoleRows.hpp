#pragma once

#include "tessellate/Model.hpp"

namespace nurbslod::gui {

// The surface a face's display normals are taken from where the B-rep says the face ends in a
// point. A degenerated edge is a pole of the face (a single 3D point, the B-rep vertex), but a
// sloppy file may leave the surface's boundary row of control points spread a little instead
// of collapsed: corpus trj7 faces 170 and 174 end in a row 0.0013 mm long at a vertex whose
// tolerance is 0.14 mm. There the derivative across the row never vanishes; it shrinks to
// 1e-4 of the other one, and du x dv turns over the last tenth of a millimetre from the
// normal of the face to one set by the row's direction, 88 degrees away (a ribbon narrower
// than a hundredth of a millimetre, twisted). No linear interpolation of corner normals
// follows that turn at any level the display draws (appearance paper, section 4.1), so the
// displayed normals and their measure would be held by an artefact of the file.
//
// So a boundary row (u or v at the end of its domain) that a degenerated edge of the face runs
// along, and whose control points all lie within the edge's vertex tolerance of their mean, is
// collapsed onto that mean (weights kept): the face's surface as the B-rep declares it, a true
// pole, whose normal near the pole is the limit normal along the face
// (BSplineSurface::normal). It moves the surface by at most the row's spread, which the vertex
// tolerance covers. Returns the face with the collapsed surface; `collapsed` (if given) gets
// the number of rows collapsed (0: the face is returned unchanged).
TrimmedSurface withPoleRowsCollapsed(const Model& model, const TrimmedSurface& face,
                                     int* collapsed = nullptr);

}  // namespace nurbslod::gui
