// The per-face LOD caches behind SoNurbsLODShape, without Coin or a GL context.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "lod/FaceLod.hpp"
#include "lod/FaceLodCache.hpp"
#include "occ/ModelImporter.hpp"

namespace nurbslod::gui {
namespace {

std::shared_ptr<const Model> sphereModel() {
    return std::make_shared<const Model>(occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape()));
}

std::shared_ptr<const Model> boxModel() {
    return std::make_shared<const Model>(
        occ::importModel(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape()));
}

// Asks for a level and waits (at most a minute) until a worker made it.
const FaceLod* makeLevel(FaceLodCache& cache, int face, int level) {
    cache.request(face, level);
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!cache.hasLevel(face, level) && std::chrono::steady_clock::now() < end) {
        cache.waitForFinished(std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
        cache.collectFinished();
        if (cache.pendingJobs() == 0 && !cache.hasLevel(face, level)) break;
    }
    int shown = -1;
    const FaceLod* lod = cache.bestCached(face, level, &shown);
    return shown == level ? lod : nullptr;
}

TEST(FaceLodCache, LevelTolerancesHalve) {
    FaceLodCache cache(sphereModel());
    const double diagonal = cache.model().boundingBoxDiagonal;
    EXPECT_DOUBLE_EQ(cache.levelTolerance(0), FaceLodCache::coarsestRelativeTolerance * diagonal);
    for (int level = 0; level < cache.finestLevel(); ++level)
        EXPECT_DOUBLE_EQ(cache.levelTolerance(level + 1), 0.5 * cache.levelTolerance(level));
    // the coarsest level within the tolerance asked for
    EXPECT_EQ(cache.levelFor(cache.levelTolerance(3)), 3);
    EXPECT_EQ(cache.levelFor(1.01 * cache.levelTolerance(3)), 3);
    EXPECT_EQ(cache.levelFor(0.99 * cache.levelTolerance(3)), 4);
    EXPECT_EQ(cache.levelFor(1e9), 0);
    EXPECT_EQ(cache.levelFor(0.0), cache.finestLevel());
    EXPECT_EQ(cache.levelFor(std::numeric_limits<double>::quiet_NaN()), cache.finestLevel());
    EXPECT_LE(cache.levelTolerance(cache.finestLevel()),
              FaceLodCache::finestRelativeTolerance * diagonal);
}

TEST(FaceLodCache, EveryFaceStartsWithTheCoarsestLevelAndRefinesInWorkers) {
    FaceLodCache cache(sphereModel());
    ASSERT_GT(cache.faceCount(), 0);
    EXPECT_TRUE(cache.failures().empty());
    int level = -1;
    const FaceLod* coarse = cache.bestCached(0, 5, &level);
    ASSERT_NE(coarse, nullptr);
    EXPECT_EQ(level, 0);  // nothing finer yet: the finest there is
    EXPECT_EQ(coarse->positions.size(), coarse->normals.size());
    EXPECT_EQ(coarse->indices.size() % 3, 0u);
    const FaceLod* fine = makeLevel(cache, 0, 4);
    ASSERT_NE(fine, nullptr);
    EXPECT_DOUBLE_EQ(fine->tolerance, cache.levelTolerance(4));
    EXPECT_GT(fine->triangleCount(), 4 * coarse->triangleCount());
    // the exact normals of a sphere point away from its centre; the vertices lie within the
    // level's tolerance of it (edge vertices are shared between faces, not on either exactly)
    for (std::size_t v = 0; v < fine->vertexCount(); ++v) {
        const Eigen::Vector3d p(fine->positions[3 * v], fine->positions[3 * v + 1],
                                fine->positions[3 * v + 2]);
        const Eigen::Vector3d n(fine->normals[3 * v], fine->normals[3 * v + 1],
                                fine->normals[3 * v + 2]);
        ASSERT_NEAR(p.norm(), 10.0, fine->tolerance);
        ASSERT_NEAR(n.norm(), 1.0, 1e-6);
        ASSERT_GT(n.dot(p.normalized()), 1.0 - 1e-5);
    }
    // the coarsest level within a wanted one is preferred to a finer one
    EXPECT_EQ(cache.bestCached(0, 0, &level), coarse);
    EXPECT_EQ(cache.bestCached(0, 2, &level), fine);
    EXPECT_EQ(level, 4);
}

TEST(FaceLodCache, ASingleFaceKeepsOnlyItsEdgesAndVertices) {
    const auto model = boxModel();
    const Model single = singleFaceModel(*model, 0);
    ASSERT_EQ(single.faces.size(), 1u);
    EXPECT_EQ(single.edges.size(), 4u);
    EXPECT_EQ(single.vertices.size(), 4u);
    for (const TrimLoop& loop : single.faces[0].loops)
        for (const TrimCurve& curve : loop.curves) {
            EXPECT_GE(curve.edge, 0);
            EXPECT_LT(curve.edge, 4);
        }
}

TEST(FaceLodCache, BordersOfAPlaneFaceAreItsFourSides) {
    FaceLodCache cache(boxModel());
    const FaceLod* lod = cache.bestCached(0, 0, nullptr);
    ASSERT_NE(lod, nullptr);
    ASSERT_FALSE(lod->borderLines.empty());
    ASSERT_EQ(lod->borderLines.size() % 2, 0u);
    // every border point lies on the face's rectangle border: at a corner coordinate
    for (std::uint32_t index : lod->borderLines) {
        int onBorder = 0;
        for (int k = 0; k < 3; ++k) {
            const float p = lod->positions[3 * std::size_t{index} + k];
            onBorder += p == lod->boxMin[k] || p == lod->boxMax[k];
        }
        EXPECT_GE(onBorder, 2);  // flat in one direction, on a side in another
    }
}

TEST(FaceLodCache, AFaceThatCannotBeImportedIsListedNotDrawn) {
    auto model = std::make_shared<Model>(*boxModel());
    model->faces[2].error = "test: cannot convert";
    FaceLodCache cache(model);
    ASSERT_EQ(cache.failures().size(), 1u);
    EXPECT_EQ(cache.failures()[0].face, 3);
    EXPECT_EQ(cache.failures()[0].reason, "test: cannot convert");
    EXPECT_EQ(cache.bestCached(2, 0, nullptr), nullptr);
    cache.request(2, 3);  // asked for anyway: nothing happens
    EXPECT_EQ(cache.pendingJobs(), 0);
}

TEST(FaceLodCache, AModelWithoutExtentIsRefused) {
    auto model = std::make_shared<Model>(*boxModel());
    model->boundingBoxDiagonal = 0;
    EXPECT_THROW(FaceLodCache cache(model), std::invalid_argument);
    model->boundingBoxDiagonal = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(FaceLodCache cache(model), std::invalid_argument);
}

TEST(FaceLodCache, MovingAPoleRetessellatesOnlyThatFace) {
    FaceLodCache cache(boxModel());
    const FaceLod* other = cache.bestCached(1, 0, nullptr);
    const FaceLod* before = cache.bestCached(0, 0, nullptr);
    const float maxBefore[3] = {before->boxMax[0], before->boxMax[1], before->boxMax[2]};
    const BSplineSurface& surface = cache.model().faces[0].surface;
    ASSERT_GE(surface.countU(), 2);
    // lift one corner pole 5 units along the face's normal direction (the flat axis)
    int flat = 0;
    for (int k = 0; k < 3; ++k)
        if (before->boxMin[k] == before->boxMax[k]) flat = k;
    Point3 corner = projectHomogeneous(surface.pole(0, 0));
    corner[flat] += 5.0;
    const double ms = cache.movePole(0, 0, 0, corner, 0);
    EXPECT_GE(ms, 0.0);
    const FaceLod* after = cache.bestCached(0, 0, nullptr);
    ASSERT_NE(after, nullptr);
    EXPECT_NE(after, before);
    EXPECT_GT(after->boxMax[flat], maxBefore[flat] + 1.0);
    EXPECT_EQ(cache.bestCached(1, 0, nullptr), other);  // the neighbour is untouched
    EXPECT_DOUBLE_EQ(projectHomogeneous(cache.model().faces[0].surface.pole(0, 0))[flat],
                     corner[flat]);
}

// A model far from the world's origin is stored next to it (Model::origin): an edit still
// gives world positions, and a replacement face, imported on its own, lands where it was.
TEST(FaceLodCache, EditsOfAModelFarFromTheOriginStayInPlace) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(1e5, 0, 0), 10.0, 20.0, 30.0).Shape();
    FaceLodCache cache(std::make_shared<const Model>(occ::importModel(box)));
    const Vector3 origin = cache.model().origin;
    ASSERT_GT(origin.x(), 9e4);  // moved: the box is 2,700 diagonals from the origin
    const FaceLod* before = cache.bestCached(0, 0, nullptr);
    ASSERT_NE(before, nullptr);
    EXPECT_NEAR(before->boxMin[0], 1e5, 0.01);  // the drawn face is where the box is
    int flat = 0;
    for (int k = 0; k < 3; ++k)
        if (before->boxMin[k] == before->boxMax[k]) flat = k;
    Point3 corner = projectHomogeneous(cache.model().faces[0].surface.pole(0, 0)) + origin;
    corner[flat] += 5.0;
    cache.movePole(0, 0, 0, corner, 0);
    const FaceLod* moved = cache.bestCached(0, 0, nullptr);
    ASSERT_NE(moved, nullptr);
    EXPECT_NEAR(moved->boxMax[flat], corner[flat], 0.01);
    EXPECT_LT(
        (projectHomogeneous(cache.model().faces[0].surface.pole(0, 0)) + origin - corner).norm(),
        1e-9);
    // face 2 replaced by itself, imported alone (its own origin is its own centre)
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(box, TopAbs_FACE, faces);
    const FaceLod* second = cache.bestCached(1, 0, nullptr);
    const float secondMin[3] = {second->boxMin[0], second->boxMin[1], second->boxMin[2]};
    const float secondMax[3] = {second->boxMax[0], second->boxMax[1], second->boxMax[2]};
    cache.replaceFace(1, occ::importModel(faces(2)), 0);
    const FaceLod* replaced = cache.bestCached(1, 0, nullptr);
    ASSERT_NE(replaced, nullptr);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(replaced->boxMin[k], secondMin[k], 0.01) << k;
        EXPECT_NEAR(replaced->boxMax[k], secondMax[k], 0.01) << k;
    }
}

TEST(FaceLodCache, BadEditsAreRefusedAndChangeNothing) {
    FaceLodCache cache(boxModel());
    const FaceLod* before = cache.bestCached(0, 0, nullptr);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(cache.movePole(0, 0, 0, Point3(nan, 0, 0), 0), std::invalid_argument);
    EXPECT_THROW(cache.movePole(0, -1, 0, Point3(0, 0, 0), 0), std::out_of_range);
    EXPECT_THROW(cache.movePole(0, 0, 99, Point3(0, 0, 0), 0), std::out_of_range);
    EXPECT_THROW(cache.movePole(99, 0, 0, Point3(0, 0, 0), 0), std::out_of_range);
    EXPECT_THROW(cache.replaceFace(0, Model{}, 0), std::invalid_argument);
    EXPECT_EQ(cache.bestCached(0, 0, nullptr), before);
}

// A pole moved a million units from a sphere of radius 10 made the edit's level (in the GUI
// thread) tessellate a face that size at the model's tolerance for more than a minute: an edit
// reaches at most 100 model diagonals from the face, and is refused beyond with the reason.
TEST(FaceLodCache, EditsFarBeyondTheModelAreRefusedAtOnce) {
    FaceLodCache cache(sphereModel());
    const FaceLod* before = cache.bestCached(0, 0, nullptr);
    const auto start = std::chrono::steady_clock::now();
    for (const double x : {1e6, 1e300}) {
        try {
            cache.movePole(0, 2, 2, Point3(x, 0, 0), 0);
            ADD_FAILURE() << "a pole at " << x << " was accepted";
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find("times the model's size"), std::string::npos)
                << error.what();
        }
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    EXPECT_EQ(cache.bestCached(0, 0, nullptr), before);
    // within reach: taken (10 diagonals out)
    EXPECT_GE(cache.movePole(0, 2, 2, Point3(10 * cache.model().boundingBoxDiagonal, 0, 0), 0),
              0.0);
    // a replacement face far away, as an edit's BREP could bring it
    const Model far = occ::importModel(BRepPrimAPI_MakeSphere(gp_Pnt(1e6, 0, 0), 10.0).Shape());
    EXPECT_THROW(cache.replaceFace(0, far, 0), std::invalid_argument);
}

TEST(FaceLodCache, ALevelMadeForTheOldSurfaceIsDroppedAfterAnEdit) {
    FaceLodCache cache(boxModel());
    cache.request(0, 6);
    const Point3 corner = projectHomogeneous(cache.model().faces[0].surface.pole(0, 0));
    cache.movePole(0, 0, 0, corner + Point3(0.5, 0.5, 0.5), 0);
    // wait for the old job, then collect: level 6 of the old surface must not appear
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (cache.pendingJobs() > 0 && std::chrono::steady_clock::now() < end)
        cache.waitForFinished(std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
    cache.collectFinished();
    EXPECT_FALSE(cache.hasLevel(0, 6));
    EXPECT_TRUE(cache.hasLevel(0, 0));
}

TEST(FaceLod, TessellationFailuresComeBackAsReasons) {
    auto model = std::make_shared<Model>(*boxModel());
    const FaceLodResult bad = tessellateFaceLod(*model, 0, -1.0);
    EXPECT_EQ(bad.lod, nullptr);
    EXPECT_FALSE(bad.failure.empty());
    model->faces[0].surface.pole(0, 0).w() = -1.0;  // a weight <= 0
    const FaceLodResult badWeight = tessellateFaceLod(*model, 0, 0.1);
    EXPECT_EQ(badWeight.lod, nullptr);
    EXPECT_NE(badWeight.failure.find("weight"), std::string::npos) << badWeight.failure;
}

}  // namespace
}  // namespace nurbslod::gui
