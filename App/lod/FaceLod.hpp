#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tessellate/Model.hpp"

namespace nurbslod::gui {

// One level of detail of one face, ready for glDrawElements with client arrays: float
// positions and the face's exact normals per vertex (the tessellator evaluates the surface
// normal at every vertex, paper out-of-core-lod 3.3), triangles as indices. Immutable once
// made, so a frame can draw it while a worker thread makes the next one.
struct FaceLod {
    double tolerance = 0;  // guaranteed distance to the surface, model units
    // Measured (measureInterpolatedNormalError): the largest angle between the normal the
    // display interpolates across a triangle and the exact normal there, over every triangle.
    double maxNormalErrorDeg = 0;
    std::vector<float> positions;        // x y z per vertex
    std::vector<float> normals;          // x y z per vertex, unit
    std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise
    // Two per segment: the mesh's border (edges of one triangle only), i.e. the face's
    // trimming loops at this level's tolerance, drawn as the face's B-rep edges.
    std::vector<std::uint32_t> borderLines;
    float boxMin[3] = {0, 0, 0};
    float boxMax[3] = {0, 0, 0};

    std::size_t triangleCount() const { return indices.size() / 3; }
    std::size_t vertexCount() const { return positions.size() / 3; }
};

// A face on its own: the face, the edges its loops use and their vertices, renumbered, so
// that one face can be tessellated without the rest of the model.
Model singleFaceModel(const Model& model, int faceIndex);

// The outcome of tessellating one face at one tolerance: a level, or why there is none.
struct FaceLodResult {
    std::shared_ptr<const FaceLod> lod;
    std::string failure;  // empty when lod is set
};

// Tessellates face faceIndex (0-based) of the model within the tolerance (guaranteed mode).
// Never throws: every failure, OpenCASCADE's included, comes back as a reason.
FaceLodResult tessellateFaceLod(const Model& model, int faceIndex, double tolerance);

}  // namespace nurbslod::gui
