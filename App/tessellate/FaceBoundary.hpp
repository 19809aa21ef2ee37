#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// Where a segment of a face's boundary polygon comes from: segment `segment` of the shared
// polyline of B-rep edge `edge`, run in the edge's direction or against it. Edge -1: a
// segment that closes a gap between two trimming curves of a sloppy loop.
struct BoundarySegmentOrigin {
    int edge = -1;
    int segment = 0;
    bool forward = true;
    int use = 0;  // which of the edge's uses: a seam edge has two in the same face

    bool operator==(const BoundarySegmentOrigin&) const = default;
};

// One corner of a face's boundary polygon in the face's (u, v) plane, carrying the id of the
// mesh vertex that the faces of its edge share.
struct BoundaryPoint {
    Point2 uv;
    std::uint32_t vertex = 0;
    // A crossing found by this face is placed at the exact integer point the clipper gave it,
    // so that it lies exactly on the cell side and makes no second crossing.
    bool exact = false;
    std::int64_t x = 0, y = 0;

    bool operator==(const BoundaryPoint&) const = default;
};

// A closed boundary polygon: segment i runs from points[i] to points[i+1] (cyclically) and
// lies on origins[i].
struct BoundaryLoop {
    std::vector<BoundaryPoint> points;
    std::vector<BoundarySegmentOrigin> origins;

    bool operator==(const BoundaryLoop&) const = default;
};

// A point where a kd-tree cell's side cuts a face's boundary between two polygon corners. To keep
// the mesh closed it must become a corner of the other face of that edge too.
struct BoundaryCrossing {
    int edge = -1;
    int segment = 0;
    int use = 0;                // the use (side of a seam) on which the face found it
    double lambda = 0;          // position along the edge segment, in the edge's direction
    std::int64_t x = 0, y = 0;  // exact integer position in the face's frame that found it
};

}  // namespace nurbslod
