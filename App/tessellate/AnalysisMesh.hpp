#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"
#include "tessellate/Mesh.hpp"
#include "tessellate/Model.hpp"

namespace nurbslod {

// The mesh a surface-analysis display draws (isophotes, reflection lines, curvature maps):
// every vertex once per face that uses it, so that each attribute is simply per vertex and a
// crease keeps its two normals. Normals and curvatures are the exact surface's at the vertex
// (appearance.txt, section 5: the display interpolates them across each triangle).
struct AnalysisMesh {
    std::vector<Point3> points;
    std::vector<Vector3> normals;    // unit, outward (the face's orientation applied)
    std::vector<Point2> parameters;  // (u, v) on the vertex's face
    std::vector<double> gaussian;    // minimum * maximum
    std::vector<double> mean;        // (minimum + maximum) / 2
    std::vector<double> minimum;     // principal curvatures, minimum <= maximum; positive
    std::vector<double> maximum;     //   where the face is convex (bends away from its normal)
    std::vector<std::array<std::uint32_t, 3>> triangles;  // into points
    std::vector<std::int32_t> triangleFaces;              // 1-based B-rep face index
    std::size_t singularVertices = 0;  // vertices at a singular point: curvature from its limit
};

// Splits the tessellator's mesh of the model into per-face vertices and evaluates the
// curvature of each vertex's face at its (u, v) (geometry/SurfaceCurvature). A vertex on a
// knot line where its surface is less than C2 is split once more, by side, and each copy is
// evaluated as the one-sided limit, so a curvature jump at a G1 joint stays sharp. The mesh must
// come from tessellateModel(model, ...), whose normals carry their (u, v) in parameters.
// Throws std::invalid_argument when the mesh does not fit the model.
AnalysisMesh analysisMesh(const Model& model, const Mesh& mesh);

}  // namespace nurbslod
