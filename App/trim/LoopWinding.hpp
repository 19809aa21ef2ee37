#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/Point.hpp"
#include "trim/TrimLoop.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// The loop's curves sampled in (u, v) in the order and direction the loop runs them,
// samplesPerCurve + 1 evenly spaced points a curve, its ends included (where the loop closes, a
// curve's end is the next one's start, and the shoelace sum of signedArea is the same as without
// the repeated points).
std::vector<Point2> loopPolygon(const TrimLoop& loop, int samplesPerCurve = 16);

// The area the polygon encloses, positive where it runs counter-clockwise.
double signedArea(const std::vector<Point2>& polygon);

// Whether p is inside the polygon (even-odd rule).
bool insidePolygon(const std::vector<Point2>& polygon, const Point2& p);

// What is wrong with the way the face's loops wind, if anything: a hole (a loop closed in
// (u, v) inside the outer loop) that runs the same way round as the outer loop. OpenCASCADE
// takes the face's material to the left of every wire (BRepCheck calls such a face
// BadOrientationOfSubshape), so the face then is not the region with a hole that it was drawn
// as; the tessellator fills its loops by the even-odd rule, which makes it that region.
std::optional<std::string> loopWindingProblem(const TrimmedSurface& face);

}  // namespace nurbslod
