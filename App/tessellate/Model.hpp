#pragma once

#include <vector>

#include "geometry/Point.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// A B-rep edge: shared by the faces that use it, discretised once for all of them.
struct ModelEdge {
    int firstVertex = -1, lastVertex = -1;  // indices into Model::vertices (B-rep vertices)
    double tolerance = 0;                   // the B-rep's own tolerance of the edge
    bool degenerated = false;
};

// A B-rep vertex.
struct ModelVertex {
    Point3 point;
    double tolerance = 0;
};

// A whole B-rep model as trimmed NURBS faces with their shared edges and vertices.
struct Model {
    std::vector<TrimmedSurface> faces;  // faces[k].faceIndex == k + 1
    std::vector<ModelEdge> edges;
    std::vector<ModelVertex> vertices;
    double boundingBoxDiagonal = 0;
};

}  // namespace nurbslod
