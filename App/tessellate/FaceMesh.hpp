#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// The triangles of one face before they join the model's mesh. A vertex is either shared with
// other faces (an edge vertex, by id) or the face's own (a surface point).
struct FaceMesh {
    struct Vertex {
        bool shared = false;
        std::uint32_t sharedId = 0;
        Point3 position = Point3::Zero();  // for the face's own vertices
        Vector3 normal = Vector3::Zero();  // the face's exact normal at the vertex
        Point2 uv = Point2::Zero();        // where the vertex lies on the face's surface
        // the position is the surface's at uv (a point of the face's own, not of an edge or of
        // a chord across an open edge)
        bool positionFromSurface = false;
    };
    std::vector<Vertex> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // into vertices, counter-clockwise
    std::size_t cells = 0;
    // A cut of a cell side with a chord of an edge (its segment, for the use of the face that
    // made it) that no other face knows: where and at which integer point of this face's frame.
    struct OpenCut {
        int edge = -1, segment = 0, use = 0;
        Point3 position = Point3::Zero();
        std::int64_t x = 0, y = 0;
    };
    std::vector<OpenCut> openCuts;
    bool toleranceReached = true;  // false where the kd-tree hit its depth limit
};

}  // namespace nurbslod
