#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "occ/ModelImporter.hpp"
#include "tessellate/FaceSurfaceCache.hpp"
#include "tessellate/FaceSurfaceNeed.hpp"
#include "tessellate/LoneFaces.hpp"

namespace nurbslod {
namespace {

// A box less a sphere: planes and a sphere cut by them, whose NURBS form has several spans.
Model boxLessSphere() {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
    const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(gp_Pnt(10, 10, 10), 6).Shape();
    return occ::importModel(BRepAlgoAPI_Cut(box, sphere).Shape());
}

TEST(FaceSurfaceCache, MakesEachFacesPatchesOnceForEveryThread) {
    const Model model = boxLessSphere();
    ASSERT_GE(model.faces.size(), 4u);
    const FaceSurfaceCache cache(model);
    const int faces = static_cast<int>(model.faces.size());
    std::vector<std::vector<const BezierPatchGrid*>> seen(
        4, std::vector<const BezierPatchGrid*>(model.faces.size(), nullptr));
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            for (int f = 0; f < faces; ++f) seen[t][f] = cache.patches(f).get();
        });
    for (auto& thread : threads) thread.join();
    for (int f = 0; f < faces; ++f) {
        ASSERT_NE(seen[0][f], nullptr);
        for (int t = 1; t < 4; ++t) EXPECT_EQ(seen[t][f], seen[0][f]) << "face " << f + 1;
        EXPECT_EQ(cache.patches(f).get(), seen[0][f]);
        // the grid is the face's own: as many spans as one made for its surface anew
        const BezierPatchGrid anew(model.faces[f].surface);
        EXPECT_EQ(seen[0][f]->spansU(), anew.spansU());
        EXPECT_EQ(seen[0][f]->spansV(), anew.spansV());
    }
}

TEST(FaceSurfaceCache, SurfaceNeedIsTheFacesForTheModeAndCapAsked) {
    const Model model = boxLessSphere();
    const FaceSurfaceCache cache(model);
    bool capsDiffer = false;
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f)
        for (const ErrorMode mode : {ErrorMode::Guaranteed, ErrorMode::Approximate}) {
            // a cap above the face's need and one under it (a plane needs none: 0 for both)
            const double need = faceSurfaceNeed(model.faces[f], mode, 1e9);
            ASSERT_TRUE(std::isfinite(need));
            for (const double cap : {2 * need + 1e-9, 0.5 * need, 2 * need + 1e-9}) {
                const double expected = faceSurfaceNeed(model.faces[f], mode, cap);
                EXPECT_EQ(cache.surfaceNeed(f, mode, cap), expected)
                    << "face " << f + 1 << " cap " << cap;
            }
            capsDiffer |= faceSurfaceNeed(model.faces[f], mode, 0.5 * need) !=
                          faceSurfaceNeed(model.faces[f], mode, 2 * need + 1e-9);
        }
    // the sphere's need is over the lower cap (infinite) and within the higher: a cache that
    // kept one value whatever the cap would fail above
    EXPECT_TRUE(capsDiffer);
}

TEST(FaceSurfaceCache, ALoneFaceTakesTheModelsPatchesAndNeed) {
    const Model model = boxLessSphere();
    const FaceSurfaceCache cache(model);
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
        const double need = cache.surfaceNeed(f, ErrorMode::Guaranteed, 0.5);
        const Model lone = loneFaceModel(model, f);
        FaceSurfaceCache loneCache(lone);
        loneCache.take(0, cache, f);
        EXPECT_EQ(loneCache.patches(0).get(), cache.patches(f).get()) << "face " << f + 1;
        EXPECT_EQ(loneCache.surfaceNeed(0, ErrorMode::Guaranteed, 0.5), need);
        // a cap not measured before is measured on the lone model's face, the same surface
        EXPECT_EQ(loneCache.surfaceNeed(0, ErrorMode::Guaranteed, 0.05),
                  faceSurfaceNeed(model.faces[f], ErrorMode::Guaranteed, 0.05));
    }
}

}  // namespace
}  // namespace nurbslod
