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
    // Where the model's coordinates start: its surfaces, edges and vertices are stored relative
    // to this point, and tessellateModel places its mesh back by it. The importer moves a model
    // that lies far from the world's origin next to it (occ/ModelImporter.cpp), so that the
    // rounding of its coordinates stays far below its tolerances; otherwise it is zero.
    Vector3 origin = Vector3::Zero();
};

}  // namespace nurbslod
