#pragma once

#include <TopoDS_Shape.hxx>
#include <cstddef>
#include <string>
#include <vector>

#include "tessellate/Mesh.hpp"

namespace nurbslod::occ {

// What the verifier measured on one B-rep face that has triangles. Distances are in model
// units and are real distances to the exact B-rep, not bounds used to build the mesh.
struct FaceDeviation {
    int face = 0;  // 1-based, TopExp::MapShapes order (FreeCAD's shape.Faces)
    std::size_t triangles = 0;
    // Mesh -> exact face: the largest deviation of a sample of the face's triangles (vertices,
    // edge midpoints, centroids, interior points), max(distance to the untrimmed surface,
    // distance to the trimmed face - edgeTolerance).
    double dev = 0;
    // Exact face -> mesh: the largest distance from a point of the exact face to the face's
    // triangles, less edgeTolerance (holes, missing strips, over-trimming).
    double cover = 0;
    // The largest tolerance of the face's edges: the B-rep's own uncertainty at its trimming
    // boundary, which real CAD files make large.
    double edgeTolerance = 0;
    // False when the face could not be measured: OpenCASCADE cannot mesh it for reference
    // (meshjudge skips such faces too) or its geometry made OpenCASCADE fail; see `problem`.
    bool measured = true;
    std::string problem;
};

// The whole verdict, with the same quantities and rules as tools/meshjudge.py.
struct VerificationReport {
    double tolerance = 0;
    int shapeFaces = 0;                   // faces of the B-rep
    std::vector<FaceDeviation> faces;     // every face that has triangles, by face number
    double maxDev = 0, maxCover = 0;      // over the measured faces
    std::vector<int> facesOverTolerance;  // dev > tolerance or cover > tolerance
    std::vector<int> facesMissing;        // no triangles but an area > tolerance^2
    std::vector<int> facesUnmeasured;     // have triangles but could not be measured
    // After welding positions that agree to max(tolerance * 1e-3, 1e-9) (cracks show as open
    // edges, which a closed solid's mesh must not have).
    std::size_t openEdges = 0, nonManifoldEdges = 0;
    std::size_t degenerateTriangles = 0;      // area ~ 0 relative to the face's largest triangle
    std::size_t triangles = 0, vertices = 0;  // vertices: welded positions used by triangles
    double seconds = 0;
    // no face over tolerance, none missing and none unmeasured: a face that could not be
    // measured is not known to be within the tolerance
    bool pass = false;
};

// Measures the deviation of the mesh from the exact B-rep, per face and both ways, as
// meshjudge defines it (see FaceDeviation), in parallel over faces. The mesh's triangleFaces
// name the face of each triangle. Throws std::invalid_argument for a tolerance that is not a
// positive finite number, a mesh whose arrays do not fit together, or a face number the shape
// does not have.
VerificationReport verifyMesh(const TopoDS_Shape& shape, const Mesh& mesh, double tolerance);

}  // namespace nurbslod::occ
