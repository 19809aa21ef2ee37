// A face whose trimming curves run a hair past its surface's domain must not get a kd-tree
// column that thin along its border: the column's fans, welded, fold into pairs of triangles on
// the same three points, one each way round, and their sides are used four times.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// tests/data/offset_plate.brep: a wavy bicubic plate thickened by 2 in FreeCAD
// (Part.BSplineSurface over 5 x 5 poles, face.makeOffsetShape(2, 1e-3, fill=True)). Its offset
// face, made a NURBS on import, has pcurves 1e-8 of its domain past the surface's end u = 1.
TEST(FramePastDomain, OffsetPlateUsesNoSideMoreThanTwice) {
    const TopoDS_Shape shape = occ::readShape(NURBSLOD_TEST_DATA_DIR "/offset_plate.brep");
    const Model model = occ::importModel(shape);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const TessellationResult result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty()) << result.failures.front().reason;
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
        for (const auto& t : result.mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = t[k], b = t[(k + 1) % 3];
                ++uses[{std::min(a, b), std::max(a, b)}];
            }
        int overused = 0, open = 0;
        for (const auto& [side, count] : uses) overused += count > 2, open += count == 1;
        EXPECT_EQ(overused, 0) << "relative " << relative;
        EXPECT_EQ(open, 0) << "relative " << relative;  // a closed solid
    }
}

}  // namespace
}  // namespace nurbslod
