#pragma once

#include <gtest/gtest.h>

#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::test {

// Checks that no face of `result` failed and that `nurbslod verify`'s measure of its mesh
// against `shape` passes both ways within `tolerance` with no open edge.
inline void expectVerified(const TopoDS_Shape& shape, const TessellationResult& result,
                           double tolerance) {
    EXPECT_TRUE(result.failures.empty());
    const auto report = occ::verifyMesh(shape, result.mesh, tolerance);
    EXPECT_TRUE(report.pass) << "max dev " << report.maxDev << " cover " << report.maxCover;
    EXPECT_LE(report.maxDev, tolerance);
    EXPECT_LE(report.maxCover, tolerance);
    EXPECT_EQ(report.openEdges, 0u);
}

// Tessellates `shape` at `tolerance` in guaranteed mode, checks it as expectVerified does, and
// returns its triangles per face (index: FreeCAD's 1-based face number; 0 unused).
inline std::vector<std::size_t> verifiedTrianglesPerFace(const TopoDS_Shape& shape,
                                                         const Model& model, double tolerance) {
    TessellationOptions options;
    options.tolerance = tolerance;
    const TessellationResult result = tessellateModel(model, options);
    expectVerified(shape, result, tolerance);
    std::vector<std::size_t> perFace(model.faces.size() + 1, 0);
    for (const auto face : result.mesh.triangleFaces) ++perFace.at(face);
    return perFace;
}

// Tessellates `shape` at `tolerance` in guaranteed mode, checks that it has `faceCount` faces,
// that none failed and that `nurbslod verify`'s measure passes both ways with no open edge,
// and returns the triangles of its face with the most.
inline std::size_t verifiedLargestFaceTriangles(const TopoDS_Shape& shape, double tolerance,
                                                std::size_t faceCount) {
    const Model model = occ::importModel(shape);
    EXPECT_EQ(model.faces.size(), faceCount);
    const std::vector<std::size_t> perFace = verifiedTrianglesPerFace(shape, model, tolerance);
    return *std::max_element(perFace.begin(), perFace.end());
}

}  // namespace nurbslod::test
