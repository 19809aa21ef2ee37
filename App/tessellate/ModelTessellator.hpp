#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessellate/Mesh.hpp"
#include "tessellate/Model.hpp"
#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

struct FaceFailure {
    int face = 0;  // 1-based
    std::string reason;
};

// The vertices a face's tessellator evaluated on the face's surface: (u, v) of each, and
// whether its position came from the surface (the face's own points) or from a shared edge
// (where only the normal was wanted).
struct FaceVertexSet {
    std::vector<Point2> uv;
    std::vector<char> needsPosition;
    // the face's own positions, before the mesh welds points closer than its weld distance
    std::vector<Point3> positions;
    // the index in mesh.normals and mesh.parameters of the first vertex; the others follow
    std::uint32_t firstNormal = 0;
};

struct TessellationResult {
    Mesh mesh;
    int faces = 0;
    double seconds = 0;
    double tolerance = 0;
    std::vector<FaceFailure> failures;
    // faces meshed, with a word on their input (TrimmedSurface::warning), in face order
    std::vector<FaceFailure> warnings;
    // per face (index face - 1), filled when TessellationOptions::keepFaceVertices is set
    std::vector<FaceVertexSet> faceVertices;
};

// The finest tolerance tessellateModel takes, as a share of the model's bounding-box diagonal.
// A sphere takes 3.2 million triangles and 1.4 GB at 1e-6 (14 s), and ten times as many with
// each tenth finer: a finer tolerance would exhaust the memory (a crash that loses FreeCAD's
// unsaved work) or run for hours (1e-20 of a sphere's size never ended) before any message.
constexpr double kFinestRelativeTolerance = 1e-6;

// The least bounding-box diagonal of a model tessellateModel takes: ten times OpenCASCADE's
// confusion distance (Precision::Confusion, 1e-7), which is also its least edge and vertex
// tolerance. Below, a vertex's tolerance ball may hold whole faces: a sphere of radius 5e-8
// (FreeCAD's makeSphere) at relative 1e-3 ran for minutes, its boundary grown to 475,000
// points, where one of 5.5e-8 took 17 ms. The workbench's display takes the same floor for
// FreeCAD's own mesher (NurbsLOD.SMALLEST_MODEL), which loops there too.
constexpr double kSmallestModel = 1e-6;

// Tessellates every face of the model within options.tolerance, sharing edge vertices between
// the faces of an edge. A face that cannot be tessellated is listed in failures with its
// reason; the others are still meshed. Throws std::invalid_argument, with the reason, for a
// tolerance that is not a positive finite number, is finer than kFinestRelativeTolerance of the
// model's diagonal, or is finer than the rounding of the model's coordinates (Model::origin),
// and for a model less than 1e-6 across (ten times OpenCASCADE's confusion distance).
TessellationResult tessellateModel(const Model& model, const TessellationOptions& options);

}  // namespace nurbslod
