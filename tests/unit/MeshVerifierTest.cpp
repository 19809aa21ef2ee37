#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <cmath>
#include <filesystem>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>
#include <limits>
#include <map>
#include <set>

#include "SampleModels.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

using nurbslod::Mesh;
using nurbslod::Point3;
using nurbslod::Vector3;
using nurbslod::occ::verifyMesh;

namespace {

// OpenCASCADE's own mesh of the shape at the given deflection and 0.1 rad (what FreeCAD's
// shape.tessellate asks for), as a Mesh whose face ids follow TopExp::MapShapes. With
// shareVertices, positions that are bit-for-bit equal (BRepMesh puts the same edge points into both
// faces of an edge) become one, as a watertight mesher's output.
Mesh brepMeshOf(const TopoDS_Shape& shape, double deflection, bool shareVertices) {
    BRepTools::Clean(shape);
    BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, 0.1, Standard_False);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    Mesh mesh;
    std::map<std::tuple<double, double, double>, std::uint32_t> shared;
    for (int f = 1; f <= faces.Extent(); ++f) {
        const TopoDS_Face& face = TopoDS::Face(faces(f));
        TopLoc_Location location;
        const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
        if (triangulation.IsNull()) continue;
        std::vector<std::uint32_t> index(triangulation->NbNodes() + 1);
        for (int i = 1; i <= triangulation->NbNodes(); ++i) {
            const gp_Pnt p = triangulation->Node(i).Transformed(location.Transformation());
            const auto key = std::make_tuple(p.X(), p.Y(), p.Z());
            const auto found = shared.find(key);
            if (shareVertices && found != shared.end()) {
                index[i] = found->second;
                continue;
            }
            index[i] = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(Point3(p.X(), p.Y(), p.Z()));
            shared.emplace(key, index[i]);
        }
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (int t = 1; t <= triangulation->NbTriangles(); ++t) {
            int a = 0, b = 0, c = 0;
            triangulation->Triangle(t).Get(a, b, c);
            if (reversed) std::swap(b, c);
            mesh.triangles.push_back({index[a], index[b], index[c]});
            mesh.triangleFaces.push_back(f);
        }
    }
    return mesh;
}

std::vector<std::uint32_t> verticesOnlyInFace(const Mesh& mesh, int face) {
    std::set<std::uint32_t> inFace, elsewhere;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t])
            (mesh.triangleFaces[t] == face ? inFace : elsewhere).insert(v);
    std::vector<std::uint32_t> result;
    for (std::uint32_t v : inFace)
        if (!elsewhere.count(v)) result.push_back(v);
    return result;
}

void expectPasses(const TopoDS_Shape& shape, double deflection) {
    const Mesh mesh = brepMeshOf(shape, deflection, true);
    const double tolerance = 2 * deflection;
    const auto report = verifyMesh(shape, mesh, tolerance);
    EXPECT_TRUE(report.pass);
    EXPECT_LE(report.maxDev, tolerance);
    EXPECT_LE(report.maxCover, tolerance);
    EXPECT_GT(report.maxDev, 1e-3 * deflection);  // a curved shape's chords do deviate
    EXPECT_TRUE(report.facesOverTolerance.empty());
    EXPECT_TRUE(report.facesMissing.empty());
    EXPECT_TRUE(report.facesUnmeasured.empty());
    EXPECT_EQ(report.triangles, mesh.triangles.size());
    for (const auto& face : report.faces) {
        EXPECT_TRUE(face.measured) << "face " << face.face << ": " << face.problem;
        EXPECT_LE(face.dev, tolerance) << "face " << face.face;
    }
}

}  // namespace

TEST(MeshVerifier, BRepMeshOfPrimitivesPasses) {
    expectPasses(BRepPrimAPI_MakeSphere(10.0).Shape(), 0.05);
    expectPasses(BRepPrimAPI_MakeCylinder(3.0, 8.0).Shape(), 0.02);
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(-1, 2, 3), 4.0, 5.0, 6.0).Shape();
    const Mesh mesh = brepMeshOf(box, 0.01, true);
    const auto report = verifyMesh(box, mesh, 0.02);
    EXPECT_TRUE(report.pass);
    EXPECT_LT(report.maxDev, 1e-9);  // flat faces: the mesh lies on them
    EXPECT_LT(report.maxCover, 1e-9);
    EXPECT_EQ(report.faces.size(), 6u);
    EXPECT_EQ(report.degenerateTriangles, 0u);
}

TEST(MeshVerifier, BoxMeshWithSharedVerticesIsClosed) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(4.0, 5.0, 6.0).Shape();
    const Mesh shared = brepMeshOf(box, 0.01, true);
    auto report = verifyMesh(box, shared, 0.02);
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(report.nonManifoldEdges, 0u);
    EXPECT_EQ(report.vertices, 8u);
    EXPECT_EQ(report.triangles, 12u);

    // per-face copies of the corners weld back together
    const Mesh separate = brepMeshOf(box, 0.01, false);
    EXPECT_EQ(separate.positions.size(), 24u);
    EXPECT_EQ(verifyMesh(box, separate, 0.02).openEdges, 0u);

    // a crack: one corner copy moved by far more than the welding grid
    Mesh cracked = separate;
    cracked.positions[0] += Vector3(1e-3, 0, 0);
    EXPECT_GT(verifyMesh(box, cracked, 0.02).openEdges, 0u);
}

TEST(MeshVerifier, VertexPushedOffTheSurfaceFailsExactlyItsFace) {
    const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(3.0, 8.0).Shape();
    const double deflection = 0.02, tolerance = 2 * deflection;
    Mesh mesh = brepMeshOf(cylinder, deflection, false);
    // the lateral face: push one of its own vertices radially outwards by 5 tolerances
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(cylinder, TopAbs_FACE, faces);
    int lateral = 0;
    for (int f = 1; f <= faces.Extent() && !lateral; ++f)
        if (BRep_Tool::Surface(TopoDS::Face(faces(f)))->DynamicType()->Name() ==
            std::string("Geom_CylindricalSurface"))
            lateral = f;
    ASSERT_GT(lateral, 0);
    const std::vector<std::uint32_t> own = verticesOnlyInFace(mesh, lateral);
    ASSERT_FALSE(own.empty());
    Point3& p = mesh.positions[own[own.size() / 2]];
    const Vector3 radial = Vector3(p.x(), p.y(), 0).normalized();
    p += 5 * tolerance * radial;

    const auto report = verifyMesh(cylinder, mesh, tolerance);
    EXPECT_FALSE(report.pass);
    EXPECT_EQ(report.facesOverTolerance, std::vector<int>{lateral});
    EXPECT_NEAR(report.maxDev, 5 * tolerance, 0.02 * tolerance);  // the vertex itself
}

TEST(MeshVerifier, VertexPushedPastTheTrimmingBoundaryFails) {
    // stays in the face's plane, so only the distance to the trimmed face can see it
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(4.0, 5.0, 6.0).Shape();
    const double tolerance = 0.02;
    Mesh mesh = brepMeshOf(box, 0.01, false);
    const int face = 1;  // x = 0
    const std::vector<std::uint32_t> own = verticesOnlyInFace(mesh, face);
    ASSERT_EQ(own.size(), 4u);
    Point3& corner = mesh.positions[own[0]];
    ASSERT_NEAR(corner.x(), 0.0, 1e-12);
    const Point3 outwards((0.0), corner.y() > 2.5 ? 1.0 : -1.0, corner.z() > 3 ? 1.0 : -1.0);
    corner += 5 * tolerance * outwards.normalized();

    const auto report = verifyMesh(box, mesh, tolerance);
    EXPECT_EQ(report.facesOverTolerance, std::vector<int>{face});
    EXPECT_NEAR(report.maxDev, 5 * tolerance, 1e-6);
}

TEST(MeshVerifier, VertexPushedPastACurvedBoundaryFails) {
    // a cylinder's cap: a rim vertex moved outwards in the cap's plane is 5 tolerances from
    // the disc (its circle), not from the cap's infinite plane
    const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(3.0, 8.0).Shape();
    const double tolerance = 0.04;
    Mesh mesh = brepMeshOf(cylinder, tolerance / 2, false);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(cylinder, TopAbs_FACE, faces);
    int cap = 0;
    for (int f = 1; f <= faces.Extent() && !cap; ++f)
        if (BRep_Tool::Surface(TopoDS::Face(faces(f)))->DynamicType()->Name() ==
            std::string("Geom_Plane"))
            cap = f;
    ASSERT_GT(cap, 0);
    const std::vector<std::uint32_t> own = verticesOnlyInFace(mesh, cap);
    std::uint32_t rim = own.front();
    for (std::uint32_t v : own)  // the vertex farthest from the axis lies on the circle
        if (mesh.positions[v].head<2>().norm() > mesh.positions[rim].head<2>().norm()) rim = v;
    Point3& p = mesh.positions[rim];
    ASSERT_NEAR(p.head<2>().norm(), 3.0, 1e-9);
    const Vector3 radial = Vector3(p.x(), p.y(), 0).normalized();
    p += 5 * tolerance * radial;

    const auto report = verifyMesh(cylinder, mesh, tolerance);
    EXPECT_EQ(report.facesOverTolerance, std::vector<int>{cap});
    EXPECT_NEAR(report.maxDev, 5 * tolerance, 1e-6);
}

TEST(MeshVerifier, ReportsMissingFacesAndHoles) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(4.0, 5.0, 6.0).Shape();
    const double tolerance = 0.02;
    const Mesh full = brepMeshOf(box, 0.01, true);

    Mesh withoutFace2;
    withoutFace2.positions = full.positions;
    for (std::size_t t = 0; t < full.triangles.size(); ++t)
        if (full.triangleFaces[t] != 2) {
            withoutFace2.triangles.push_back(full.triangles[t]);
            withoutFace2.triangleFaces.push_back(full.triangleFaces[t]);
        }
    auto report = verifyMesh(box, withoutFace2, tolerance);
    EXPECT_FALSE(report.pass);
    EXPECT_EQ(report.facesMissing, std::vector<int>{2});
    EXPECT_TRUE(report.facesOverTolerance.empty());
    EXPECT_EQ(report.openEdges, 4u);

    // half of face 3 gone: the exact face is no longer covered
    Mesh halfFace3 = full;
    for (std::size_t t = 0; t < halfFace3.triangles.size(); ++t)
        if (halfFace3.triangleFaces[t] == 3) {
            halfFace3.triangles.erase(halfFace3.triangles.begin() + t);
            halfFace3.triangleFaces.erase(halfFace3.triangleFaces.begin() + t);
            break;
        }
    report = verifyMesh(box, halfFace3, tolerance);
    EXPECT_EQ(report.facesOverTolerance, std::vector<int>{3});
    EXPECT_GT(report.maxCover, 1.0);
    EXPECT_LT(report.maxDev, 1e-9);
}

TEST(MeshVerifier, CountsDegenerateTriangles) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(4.0, 5.0, 6.0).Shape();
    Mesh mesh = brepMeshOf(box, 0.01, true);
    const auto corner = mesh.triangles[0];
    mesh.triangles.push_back({corner[0], corner[1], corner[1]});
    mesh.triangleFaces.push_back(mesh.triangleFaces[0]);
    EXPECT_EQ(verifyMesh(box, mesh, 0.02).degenerateTriangles, 1u);
}

TEST(MeshVerifier, RefusesBadArguments) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(4.0, 5.0, 6.0).Shape();
    Mesh mesh = brepMeshOf(box, 0.01, true);
    EXPECT_THROW(verifyMesh(box, mesh, 0.0), std::invalid_argument);
    EXPECT_THROW(verifyMesh(box, mesh, -1.0), std::invalid_argument);
    EXPECT_THROW(verifyMesh(box, mesh, std::nan("")), std::invalid_argument);
    EXPECT_THROW(verifyMesh(box, mesh, std::numeric_limits<double>::infinity()),
                 std::invalid_argument);
    Mesh wrongFace = mesh;
    wrongFace.triangleFaces[0] = 7;
    try {
        verifyMesh(box, wrongFace, 0.02);
        FAIL() << "accepted a face the box does not have";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("Face7"), std::string::npos);
    }
    Mesh wrongIndex = mesh;
    wrongIndex.triangles[0][0] = 1000;
    EXPECT_THROW(verifyMesh(box, wrongIndex, 0.02), std::invalid_argument);
}

TEST(MeshVerifier, CorpusBoltMeshedByBRepMeshPasses) {
    const std::filesystem::path model =
        std::filesystem::path(NURBSLOD_CORPUS_DIR) / "bug3883_xr2-ct-214_bolt.stp";
    if (!std::filesystem::exists(model)) GTEST_SKIP() << "no corpus at " << NURBSLOD_CORPUS_DIR;
    const TopoDS_Shape shape = nurbslod::occ::readShape(model.string());
    const Mesh mesh = brepMeshOf(shape, 0.04, false);
    const auto report = verifyMesh(shape, mesh, 0.04);
    // FreeCAD's mesh of the bolt: meshjudge passes all 7 faces; its exact check of the samples
    // puts the largest deviation at 0.00233 (its own summary says 0.0159 on two cylinders,
    // where Open3D's float distance to the long reference slivers is off by 0.02)
    EXPECT_TRUE(report.pass);
    EXPECT_EQ(report.faces.size(), 7u);
    EXPECT_NEAR(report.maxDev, 0.00233, 0.0002);
    EXPECT_NEAR(report.maxCover, 0.00233, 0.0002);
    EXPECT_EQ(report.openEdges, 0u);
}

TEST(MeshVerifier, ClassifiesManyBorderSamplesOnSeveralThreadsAtOnce) {
    // A square plate with nine round holes, its mesh lifted off the plane by 0.6 T: every
    // sample is 0.6 T off the surface, so each one near a border is classified against all ten
    // wires, hundreds at once on every thread. OpenCASCADE's classifier walks its wires in a
    // sequence that caches the last node it found, so one classifier shared between threads
    // crashed now and then; repeating the run makes such a race likely to show.
    BRepBuilderAPI_MakePolygon square(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 10, 0),
                                      gp_Pnt(0, 10, 0), Standard_True);
    BRepBuilderAPI_MakeFace plate(gp_Pln(gp::XOY()), square.Wire());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const gp_Circ circle(gp_Ax2(gp_Pnt(2 + 3 * i, 2 + 3 * j, 0), -gp::DZ()), 0.5);
            plate.Add(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)).Wire());
        }
    ASSERT_TRUE(plate.IsDone());
    const TopoDS_Shape face = plate.Shape();
    const double tolerance = 0.01, offset = 0.6 * tolerance;
    Mesh mesh = brepMeshOf(face, tolerance / 8, false);
    ASSERT_GT(mesh.triangles.size(), 500u);
    for (Point3& p : mesh.positions) p.z() += offset;

    const auto first = verifyMesh(face, mesh, tolerance);
    ASSERT_TRUE(first.pass);
    // chords across a hole's rim lie up to their sag (T / 8) outside the face
    ASSERT_GE(first.maxDev, offset - 1e-9);
    ASSERT_LE(first.maxDev, std::hypot(offset, tolerance / 8) + 1e-9);
    for (int run = 1; run < 8; ++run) {
        const auto report = verifyMesh(face, mesh, tolerance);
        ASSERT_TRUE(report.pass) << "run " << run;
        ASSERT_NEAR(report.maxDev, first.maxDev, 1e-9) << "run " << run;
    }
}

// A tolerance whose reference mesh would need a deflection within OpenCASCADE's confusion
// distance cannot be measured: the faces are reported unmeasured, with the reason, and the
// mesh does not pass (it was not shown to be within the tolerance).
TEST(MeshVerifier, ToleranceTooSmallToMeasureDoesNotPass) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(1e-3, 2e-3, 1e-3).Shape();
    const Mesh mesh = brepMeshOf(box, 1e-5, true);
    const auto tiny = verifyMesh(box, mesh, 5e-7);
    EXPECT_FALSE(tiny.pass);
    EXPECT_EQ(tiny.facesUnmeasured.size(), 6u);
    ASSERT_FALSE(tiny.faces.empty());
    EXPECT_NE(tiny.faces.front().problem.find("too small"), std::string::npos)
        << tiny.faces.front().problem;
    // the same planar mesh at a measurable tolerance passes
    EXPECT_TRUE(verifyMesh(box, mesh, 1e-5).pass);
}

// trj7_b1-ec-214.stp's face 311 is one that BRepMesh leaves empty (FreeCAD shows nothing
// there; meshjudge skips it): the verifier measures it against a grid on its surface instead,
// and a mesh with that face moved off by twice the tolerance fails there.
TEST(MeshVerifier, FaceThatBRepMeshLeavesEmptyIsMeasuredOnAGrid) {
    const std::filesystem::path path =
        std::filesystem::path(NURBSLOD_CORPUS_DIR) / "trj7_b1-ec-214.stp";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus not found at " << path;
    const TopoDS_Shape shape = nurbslod::occ::readShape(path.string());
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    const TopoDS_Face face = TopoDS::Face(faces(311));
    ASSERT_TRUE(brepMeshOf(face, 0.01, false).triangles.empty());  // BRepMesh gives nothing

    // the face alone, meshed on a fine grid of its own surface, the cells with a corner
    // outside the face left out
    const double tolerance = 0.3;  // about trj7's at relative 1e-3
    Mesh mesh;
    {
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        const int n = 120;
        BRepTopAdaptor_FClass2d classifier(face, Precision::Confusion());
        auto inside = [&](int i, int j) {
            return classifier.Perform(gp_Pnt2d(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n)) !=
                   TopAbs_OUT;
        };
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const gp_Pnt p = surface->Value(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n);
                mesh.positions.push_back(Point3(p.X(), p.Y(), p.Z()));
            }
        for (std::uint32_t i = 0; i < n; ++i)
            for (std::uint32_t j = 0; j < n; ++j) {
                if (!inside(i, j) || !inside(i + 1, j) || !inside(i, j + 1) ||
                    !inside(i + 1, j + 1))
                    continue;
                const std::uint32_t a = i * (n + 1) + j, b = a + n + 1;
                mesh.triangles.push_back({a, b, b + 1});
                mesh.triangles.push_back({a, b + 1, a + 1});
            }
        mesh.triangleFaces.assign(mesh.triangles.size(), 311);
    }
    const auto report = verifyMesh(shape, mesh, tolerance);
    ASSERT_EQ(report.faces.size(), 1u);
    EXPECT_TRUE(report.faces.front().measured) << report.faces.front().problem;
    EXPECT_TRUE(report.facesUnmeasured.empty());
    EXPECT_LT(report.faces.front().dev, 0.5 * tolerance);    // chords of 120 x 120 cells
    EXPECT_LT(report.faces.front().cover, 0.5 * tolerance);  // and the strip they leave

    // the same mesh moved off along z by twice the tolerance
    for (Point3& p : mesh.positions) p.z() += 2 * tolerance;
    const auto moved = verifyMesh(shape, mesh, tolerance);
    ASSERT_EQ(moved.faces.size(), 1u);
    EXPECT_TRUE(moved.faces.front().measured);
    EXPECT_GT(moved.faces.front().dev, tolerance);
    EXPECT_GT(moved.faces.front().cover, tolerance);
    EXPECT_FALSE(moved.pass);
}

namespace {

// The unit square in the plane z = 0 as a grid of n x n cells, two triangles each, with one
// vertex near the middle raised by `bump`.
Mesh squareGrid(int n, double bump) {
    Mesh mesh;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            mesh.positions.push_back(Point3(double(i) / n, double(j) / n, 0));
    mesh.positions[(n / 2) * (n + 1) + n / 2].z() = bump;
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            mesh.triangleFaces.insert(mesh.triangleFaces.end(), 2, 1);
        }
    return mesh;
}

}  // namespace

// A face of more than 50,000 triangles is measured against a reference at tolerance / 3: the
// measure still sees a vertex off the face, and passes the face without it.
TEST(MeshVerifier, FaceOfManyTrianglesIsMeasuredAgainstACoarserReference) {
    const TopoDS_Shape square = BRepBuilderAPI_MakeFace(gp_Pln(), 0, 1, 0, 1).Face();
    const double tolerance = 1e-3;
    const auto flat = verifyMesh(square, squareGrid(160, 0), tolerance);  // 51,200 triangles
    ASSERT_EQ(flat.faces.size(), 1u);
    EXPECT_TRUE(flat.faces.front().measured) << flat.faces.front().problem;
    EXPECT_TRUE(flat.pass);
    const auto bumped = verifyMesh(square, squareGrid(160, 2 * tolerance), tolerance);
    EXPECT_TRUE(bumped.faces.front().measured);
    EXPECT_NEAR(bumped.maxDev, 2 * tolerance, 1e-9);
    EXPECT_FALSE(bumped.pass);
}

// A face of more than 200,000 triangles is left unmeasured, with the reason, before any
// reference mesh is made.
TEST(MeshVerifier, FaceTooLargeForItsReferenceIsLeftUnmeasured) {
    const TopoDS_Shape square = BRepBuilderAPI_MakeFace(gp_Pln(), 0, 1, 0, 1).Face();
    const auto report = verifyMesh(square, squareGrid(320, 0), 1e-3);  // 204,800 triangles
    ASSERT_EQ(report.faces.size(), 1u);
    EXPECT_FALSE(report.faces.front().measured);
    EXPECT_NE(report.faces.front().problem.find("too large"), std::string::npos);
    EXPECT_EQ(report.facesUnmeasured, std::vector<int>{1});
    EXPECT_FALSE(report.pass);
}

// OpenCASCADE's sample MAT.brep (one bumpy B-spline face of 80 x 83 poles): its guaranteed
// mesh at relative 1e-3 (15,976 triangles) was measured against a reference at tolerance / 10
// with meshjudge's angular bound, 739,960 triangles (10 GB, 190 s); without the angular bound
// 91,762 (0.3 GB, 4 s), with the same deviation.
TEST(MeshVerifier, BumpyFaceIsMeasuredWithoutTheAngularBound) {
    const auto shape =
        nurbslod::test::sampleModel(nurbslod::test::kOpenCascadeSamples / "MAT.brep");
    if (!shape) GTEST_SKIP() << "OpenCASCADE's samples not found";
    const nurbslod::Model model = nurbslod::occ::importModel(*shape);
    nurbslod::TessellationOptions options;
    options.tolerance = 1e-3 * model.boundingBoxDiagonal;
    const auto result = nurbslod::tessellateModel(model, options);
    ASSERT_GT(result.mesh.triangles.size(), 10000u);
    const auto report = verifyMesh(*shape, result.mesh, options.tolerance);
    ASSERT_EQ(report.faces.size(), 1u);
    EXPECT_TRUE(report.faces.front().measured) << report.faces.front().problem;
    EXPECT_GT(report.maxDev, 0.5 * options.tolerance);
    EXPECT_TRUE(report.pass) << "dev " << report.maxDev << " cover " << report.maxCover;
}
