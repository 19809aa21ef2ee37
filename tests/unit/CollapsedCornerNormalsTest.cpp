// Display normals at (nearly) collapsed corners: each triangle's own normal there, chosen by
// the interpolated normal error it measures.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "SingleFaceMesh.hpp"
#include "lod/CollapsedCornerNormals.hpp"
#include "lod/FaceLod.hpp"
#include "lod/InterpolatedNormalError.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::gui {
namespace {

using testing::singleFaceMesh;

// Per triangle, the measured error (degrees).
std::vector<double> triangleErrors(const Mesh& mesh, const TrimmedSurface& face) {
    const InterpolatedNormalSampler sampler(mesh, face);
    std::vector<double> errors;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        errors.push_back(sampler.triangleMaxDeg(t));
    return errors;
}

TEST(CollapsedCornerNormals, NeverMakeATriangleWorseAtPolesAndTips) {
    // a sphere's poles (a true limit normal) and a cone's tip (no limit normal)
    const Model sphere = occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape());
    const Model cone = occ::importModel(BRepPrimAPI_MakeCone(5.0, 0.0, 10.0).Shape());
    for (const Model* model : {&sphere, &cone}) {
        for (std::size_t f = 0; f < model->faces.size(); ++f) {
            Mesh mesh = singleFaceMesh(*model, static_cast<int>(f), 0.05);
            const std::vector<double> before = triangleErrors(mesh, model->faces[f]);
            const std::size_t normals = mesh.normals.size();
            const int changed = takeCollapsedCornerNormalsInside(mesh, model->faces[f]);
            EXPECT_EQ(mesh.normals.size(), normals + static_cast<std::size_t>(changed));
            EXPECT_EQ(mesh.parameters.size(), mesh.normals.size());
            const std::vector<double> after = triangleErrors(mesh, model->faces[f]);
            for (std::size_t t = 0; t < before.size(); ++t)
                EXPECT_LE(after[t], before[t] + 1e-12) << "face " << f << " triangle " << t;
        }
    }
    Mesh empty;
    EXPECT_EQ(takeCollapsedCornerNormalsInside(empty, sphere.faces[0]), 0);
}

TEST(CollapsedCornerNormals, MendTheSloppyPoleOfCorpusTrj7) {
    // Faces 170 and 174 of trj7 end in an edge of 0.0013 mm: the vertex there carries the
    // normal of the 0.01 mm sliver beside it, 85 degrees off the rest of the face. Measured:
    // 70.3 -> 0.92 degrees at level 5, 63.7 -> 1.48 at level 8 (face 174; 170 alike).
    const std::filesystem::path path =
        std::filesystem::path(NURBSLOD_CORPUS_DIR) / "trj7_b1-ec-214.stp";
    if (!std::filesystem::is_regular_file(path)) GTEST_SKIP() << "corpus not found at " << path;
    const Model model = occ::importModel(occ::readShape(path.string()));
    ASSERT_GE(model.faces.size(), 174u);
    for (int face : {173}) {
        for (int level : {5, 8}) {
            const double tolerance = 1e-2 * model.boundingBoxDiagonal * std::ldexp(1.0, -level);
            Mesh mesh = singleFaceMesh(model, face, tolerance);
            const TrimmedSurface& surface = model.faces[static_cast<std::size_t>(face)];
            const double before = measureInterpolatedNormalError(mesh, surface).maxDeg;
            EXPECT_GT(before, 30.0) << "face " << face + 1 << " level " << level;
            EXPECT_GT(takeCollapsedCornerNormalsInside(mesh, surface), 0);
            const double after = measureInterpolatedNormalError(mesh, surface).maxDeg;
            std::printf("face %d level %d: %.3f -> %.3f degrees\n", face + 1, level, before, after);
            EXPECT_LT(after, 5.0) << "face " << face + 1 << " level " << level;
        }
    }
}

}  // namespace
}  // namespace nurbslod::gui
