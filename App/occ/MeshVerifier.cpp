#include "occ/MeshVerifier.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepExtrema_ExtPC.hxx>
#include <BRepExtrema_ExtPF.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BVH_Distance.hxx>
#include <BVH_Tools.hxx>
#include <BVH_Triangulation.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "occ/SignalsAsFailures.hpp"

namespace nurbslod::occ {

namespace {

// meshjudge's constants: its reference mesh is made at tolerance / 10, it re-checks exactly
// every sample the reference puts past half the tolerance (at least the worst 8, at most
// 2000; we allow 4000), and it samples a face's triangles at up to 200000 points.
constexpr double referenceDivisor = 10.0;
constexpr double exactCheckFraction = 0.5;
constexpr std::size_t minimumExactChecks = 8;
constexpr std::size_t maximumExactChecks = 4000;
constexpr std::size_t samplesPerFaceBudget = 200000;
// The reference for a face of many triangles. BRepMesh's reference at tolerance / 10 with
// meshjudge's angular bound grows far faster than the face's own mesh where the surface's normal
// turns a lot: OpenCASCADE's sample MAT.brep (one bumpy B-spline face of 80 x 83 poles), whose
// guaranteed mesh has 15,166 triangles at relative 1e-3, got a reference of 739,960 (10 GB,
// 190 s), and at 1e-4 (81,247) one past 15 GB. A face with more than
// `trianglesForAngledReference` triangles takes the reference without the angular bound
// (0.5 rad, the benchmark's BRepMesh; the linear deflection is its bound either way), and one
// with more than `trianglesForFineReference` a reference at tolerance / 3: MAT.brep at 1e-4 then
// 283,210 reference triangles (14 s, 0.9 GB), the generated revolved_profile.brep at 1e-4
// (51,229) 304,979 (5 s, 0.3 GB). The deviation is measured by projecting onto the exact
// surface either way; a coarser reference has fewer points at which the cover is measured, and
// more samples near its border to classify exactly. A face of more than
// `mostTrianglesToMeasure` is left unmeasured, with the reason.
constexpr std::size_t trianglesForAngledReference = 10000;
constexpr std::size_t trianglesForFineReference = 50000;
constexpr std::size_t mostTrianglesToMeasure = 200000;
constexpr double coarseReferenceDivisor = 3.0, coarseReferenceAngle = 0.5;
// meshjudge's reference mesh is FreeCAD's shape.tessellate, which asks BRepMesh for
// min(0.1, 5 * deflection + 0.005) rad (FreeCAD's defaultAngularDeflection: BRepMesh misses
// linear deflections on NURBS, so FreeCAD bounds the angle too). That angle depends on the
// model's units and, for deflections under 0.009 units, makes reference meshes of millions of
// triangles per face (meshjudge: 945 s and 8 GB on corpus/wing.brep); there we stop at
// 0.05 rad, which the linear deflection still backs.
constexpr double coarsestReferenceAngle = 0.1, finestReferenceAngle = 0.05;
double referenceAngularDeflection(double linearDeflection) {
    return std::clamp(linearDeflection * 5 + 0.005, finestReferenceAngle, coarsestReferenceAngle);
}

// Interior sample points of a triangle as barycentric weights (vertices, edge midpoints and
// the centroid are sampled separately): spread over the triangle, deterministic so that two
// runs report the same numbers.
constexpr std::array<std::array<double, 3>, 8> interiorWeights{{
    {4.0 / 6, 1.0 / 6, 1.0 / 6},
    {1.0 / 6, 4.0 / 6, 1.0 / 6},
    {1.0 / 6, 1.0 / 6, 4.0 / 6},
    {1.0 / 6, 5.0 / 12, 5.0 / 12},
    {5.0 / 12, 1.0 / 6, 5.0 / 12},
    {5.0 / 12, 5.0 / 12, 1.0 / 6},
    {0.45, 0.45, 0.10},
    {0.10, 0.45, 0.45},
}};

gp_Pnt toOcc(const Point3& p) {
    return gp_Pnt(p.x(), p.y(), p.z());
}
Point3 fromOcc(const gp_Pnt& p) {
    return Point3(p.X(), p.Y(), p.Z());
}

struct ClosestPoint {
    double squaredDistance = std::numeric_limits<double>::infinity();
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();  // barycentric, of the triangle's corners
};

ClosestPoint closestPointOnSegment(const Point3& p, const Point3& a, const Point3& b, int ia,
                                   int ib) {
    const Vector3 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    ClosestPoint result;
    result.squaredDistance = (a + t * ab - p).squaredNorm();
    result.weights[ia] = 1 - t;
    result.weights[ib] = t;
    return result;
}

// Ericson, Real-Time Collision Detection, 5.1.5, with a fallback to the edges for triangles
// of zero area (the region tests would divide by zero).
ClosestPoint closestPointOnTriangle(const Point3& p, const Point3& a, const Point3& b,
                                    const Point3& c) {
    const Vector3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    ClosestPoint result;
    if (d1 <= 0 && d2 <= 0) {
        result.weights = {1, 0, 0};
        result.squaredDistance = ap.squaredNorm();
        return result;
    }
    const Vector3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) {
        result.weights = {0, 1, 0};
        result.squaredDistance = bp.squaredNorm();
        return result;
    }
    const Vector3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) {
        result.weights = {0, 0, 1};
        result.squaredDistance = cp.squaredNorm();
        return result;
    }
    const double vc = d1 * d4 - d3 * d2;
    const double vb = d5 * d2 - d1 * d6;
    const double va = d3 * d6 - d5 * d4;
    const double denominator = va + vb + vc;
    if (!(denominator > 0)) {
        ClosestPoint best = closestPointOnSegment(p, a, b, 0, 1);
        for (ClosestPoint edge :
             {closestPointOnSegment(p, b, c, 1, 2), closestPointOnSegment(p, c, a, 2, 0)})
            if (edge.squaredDistance < best.squaredDistance) best = edge;
        return best;
    }
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return closestPointOnSegment(p, a, b, 0, 1);
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return closestPointOnSegment(p, a, c, 0, 2);
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return closestPointOnSegment(p, b, c, 1, 2);
    const double v = vb / denominator, w = vc / denominator;
    result.weights = {1 - v - w, v, w};
    result.squaredDistance = (a + v * ab + w * ac - p).squaredNorm();
    return result;
}

// Nearest-triangle queries on a fixed triangle set through OpenCASCADE's BVH.
class TriangleSetDistance {
public:
    struct Nearest {
        double distance = std::numeric_limits<double>::infinity();
        int triangle = -1;  // index into the triangles given to the constructor
        Eigen::Vector3d weights = Eigen::Vector3d::Zero();
    };

    TriangleSetDistance(const std::vector<Point3>& points,
                        const std::vector<std::array<int, 3>>& triangles)
        : points_(points), triangles_(triangles), set_(new BVH_Triangulation<double, 3>()) {
        set_->Vertices.reserve(points.size());
        for (const Point3& p : points) set_->Vertices.push_back(BVH_Vec3d(p.x(), p.y(), p.z()));
        set_->Elements.reserve(triangles.size());
        for (std::size_t t = 0; t < triangles.size(); ++t)
            set_->Elements.push_back(
                BVH_Vec4i(triangles[t][0], triangles[t][1], triangles[t][2], static_cast<int>(t)));
        set_->MarkDirty();
        set_->BVH();  // build now: later queries from many threads only read it
    }

    // `hint`: a triangle likely to be near, such as the previous sample's nearest; starting
    // from its distance lets the search skip most of the tree.
    Nearest nearest(const Point3& p, int hint = -1) const {
        Query query(points_);
        query.SetBVHSet(set_.get());
        query.SetObject(BVH_Vec3d(p.x(), p.y(), p.z()));
        if (hint >= 0) {
            const auto& t = triangles_[hint];
            const ClosestPoint closest =
                closestPointOnTriangle(p, points_[t[0]], points_[t[1]], points_[t[2]]);
            query.start(hint, closest);
        }
        query.ComputeDistance();
        Nearest result = query.best;
        result.distance = std::sqrt(result.distance);
        return result;
    }

private:
    class Query : public BVH_Distance<double, 3, BVH_Vec3d, BVH_Triangulation<double, 3>> {
    public:
        explicit Query(const std::vector<Point3>& points) : points_(points) {}

        void start(int triangle, const ClosestPoint& closest) {
            myDistance = closest.squaredDistance;
            best.distance = closest.squaredDistance;
            best.triangle = triangle;
            best.weights = closest.weights;
        }

        Standard_Boolean RejectNode(const BVH_Vec3d& cornerMin, const BVH_Vec3d& cornerMax,
                                    double& metric) const override {
            metric = BVH_Tools<double, 3>::PointBoxSquareDistance(myObject, cornerMin, cornerMax);
            return RejectMetric(metric);
        }

        Standard_Boolean Accept(const Standard_Integer index, const double&) override {
            const BVH_Vec4i& element = myBVHSet->Elements[index];
            const Point3 p(myObject.x(), myObject.y(), myObject.z());
            const ClosestPoint closest = closestPointOnTriangle(
                p, points_[element.x()], points_[element.y()], points_[element.z()]);
            if (closest.squaredDistance >= myDistance) return Standard_False;
            myDistance = closest.squaredDistance;
            best.distance = closest.squaredDistance;
            best.triangle = element.w();
            best.weights = closest.weights;
            return Standard_True;
        }

        Nearest best;

    private:
        const std::vector<Point3>& points_;
    };

    std::vector<Point3> points_;
    std::vector<std::array<int, 3>> triangles_;
    std::unique_ptr<BVH_Triangulation<double, 3>> set_;
};

// The exact distance from a point to a trimmed face, its edges and vertices included, as
// BRepExtrema_DistShapeShape(vertex, face) measures it (meshjudge's distToShape), with the
// extrema set up once per face instead of once per point.
class TrimmedFaceDistance {
public:
    explicit TrimmedFaceDistance(const TopoDS_Face& face) : face_(face) {
        interior_.Initialize(face, Extrema_ExtFlag_MINMAX, Extrema_ExtAlgo_Grad);
        TopTools_IndexedMapOfShape edges, vertices;
        TopExp::MapShapes(face, TopAbs_EDGE, edges);
        TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
        for (int i = 1; i <= edges.Extent(); ++i) {
            const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
            if (BRep_Tool::Degenerated(edge) || !BRep_Tool::IsGeometric(edge)) continue;
            edges_.push_back(std::make_unique<BRepExtrema_ExtPC>());
            edges_.back()->Initialize(edge);
        }
        for (int i = 1; i <= vertices.Extent(); ++i)
            vertexPoints_.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(i))));
    }

    double distance(const gp_Pnt& p) {
        TopoDS_Vertex vertex;
        BRep_Builder().MakeVertex(vertex, p, Precision::Confusion());
        double best = std::numeric_limits<double>::infinity();
        for (const gp_Pnt& q : vertexPoints_) best = std::min(best, p.SquareDistance(q));
        for (const auto& edge : edges_) {
            edge->Perform(vertex);
            if (edge->IsDone())
                for (int i = 1; i <= edge->NbExt(); ++i)
                    best = std::min(best, edge->SquareDistance(i));
        }
        interior_.Perform(vertex, face_);
        if (interior_.IsDone())
            for (int i = 1; i <= interior_.NbExt(); ++i)
                best = std::min(best, interior_.SquareDistance(i));
        return std::sqrt(best);
    }

private:
    TopoDS_Face face_;
    BRepExtrema_ExtPF interior_;
    std::vector<std::unique_ptr<BRepExtrema_ExtPC>> edges_;
    std::vector<gp_Pnt> vertexPoints_;
};

// OpenCASCADE's mesh of the face alone at tolerance / 10: its vertices lie on the exact face
// (interior ones on the surface, boundary ones on the edges), and each carries its (u, v).
struct ReferenceMesh {
    std::vector<Point3> points;
    std::vector<gp_Pnt2d> parameters;  // empty when OpenCASCADE gave none
    std::vector<std::array<int, 3>> triangles;
    // Triangles within two rings of the mesh's border (the face's boundary, and the seam of a
    // closed surface, where BRepMesh doubles the nodes): only a point near one of them can
    // project outside the trimmed face.
    std::vector<char> nearBorder;
};

// Marks the triangles that touch the border, then those that touch those.
std::vector<char> trianglesNearBorder(const std::vector<std::array<int, 3>>& triangles,
                                      std::size_t nodeCount) {
    std::vector<std::pair<int, int>> edges;
    edges.reserve(triangles.size() * 3);
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    std::vector<char> marked(nodeCount, 0);
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) marked[edges[i].first] = marked[edges[i].second] = 1;
        i = j;
    }
    std::vector<char> near(triangles.size(), 0);
    for (int ring = 0; ring < 2; ++ring) {
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                if (marked[triangles[t][k]]) near[t] = 1;
        for (std::size_t t = 0; t < triangles.size(); ++t)
            if (near[t])
                for (int k = 0; k < 3; ++k) marked[triangles[t][k]] = 1;
    }
    return near;
}

// BRepMesh's triangulation of the face alone, and its location. A copy: meshing the shape's own
// face would write triangulations into edges that the neighbouring faces, measured on other
// threads, share.
Handle(Poly_Triangulation)
    triangulationOfCopy(const TopoDS_Face& face, double deflection, double angularDeflection,
                        TopLoc_Location& location) {
    BRepBuilderAPI_Copy copier(face, Standard_True, Standard_False);
    const TopoDS_Face copy = TopoDS::Face(copier.Shape());
    BRepMesh_IncrementalMesh mesher(copy, deflection, Standard_False, angularDeflection,
                                    Standard_False);
    return BRep_Tool::Triangulation(copy, location);
}

ReferenceMesh referenceMeshOf(const TopoDS_Face& face, double deflection, double angle) {
    ReferenceMesh result;
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation =
        triangulationOfCopy(face, deflection, angle, location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0) return result;
    const gp_Trsf& transformation = location.Transformation();
    for (int i = 1; i <= triangulation->NbNodes(); ++i)
        result.points.push_back(fromOcc(triangulation->Node(i).Transformed(transformation)));
    if (triangulation->HasUVNodes())
        for (int i = 1; i <= triangulation->NbNodes(); ++i)
            result.parameters.push_back(triangulation->UVNode(i));
    for (int i = 1; i <= triangulation->NbTriangles(); ++i) {
        int a = 0, b = 0, c = 0;
        triangulation->Triangle(i).Get(a, b, c);
        result.triangles.push_back({a - 1, b - 1, c - 1});
    }
    result.nearBorder = trianglesNearBorder(result.triangles, result.points.size());
    return result;
}

// Projects points onto the untrimmed surface: Newton iteration on the squared distance from a
// good starting (u, v), with OpenCASCADE's global projection (ShapeAnalysis_Surface) where
// Newton does not converge. ShapeAnalysis_Surface's own seeded projection gives up on Newton
// for most points that are not on the surface and is then several times slower.
class SurfaceProjector {
public:
    struct Foot {
        gp_Pnt2d parameters;
        double distance = 0;
    };

    explicit SurfaceProjector(const Handle(Geom_Surface) & surface)
        : surface_(surface), adaptor_(surface), fallback_(new ShapeAnalysis_Surface(surface)) {
        uFirst_ = adaptor_.FirstUParameter();
        uLast_ = adaptor_.LastUParameter();
        vFirst_ = adaptor_.FirstVParameter();
        vLast_ = adaptor_.LastVParameter();
        uPeriodic_ = adaptor_.IsUPeriodic();
        vPeriodic_ = adaptor_.IsVPeriodic();
    }

    Foot project(const gp_Pnt& p, const gp_Pnt2d& seed, double precision) {
        double u = seed.X(), v = seed.Y();
        double seedDistance = -1;
        for (int iteration = 0; iteration < 32; ++iteration) {
            gp_Pnt s;
            gp_Vec su, sv, suu, svv, suv;
            adaptor_.D2(u, v, s, su, sv, suu, svv, suv);
            const gp_Vec r(p, s);
            const double distance = r.Magnitude();
            if (seedDistance < 0) seedDistance = distance;
            const double fu = r.Dot(su), fv = r.Dot(sv);
            double a = su.Dot(su) + r.Dot(suu), b = su.Dot(sv) + r.Dot(suv),
                   c = sv.Dot(sv) + r.Dot(svv);
            double determinant = a * c - b * b;
            if (!(a > 0 && determinant > 0)) {
                // not convex here: Gauss-Newton, whose matrix is the first fundamental form
                a = su.Dot(su);
                b = su.Dot(sv);
                c = sv.Dot(sv);
                determinant = a * c - b * b;
                if (!(determinant > 0)) break;
            }
            const double du = -(c * fu - b * fv) / determinant;
            const double dv = -(a * fv - b * fu) / determinant;
            const double nextU = uPeriodic_ ? u + du : std::clamp(u + du, uFirst_, uLast_);
            const double nextV = vPeriodic_ ? v + dv : std::clamp(v + dv, vFirst_, vLast_);
            const double step = (su * (nextU - u) + sv * (nextV - v)).Magnitude();
            if (!std::isfinite(step)) break;
            if (step < precision) {
                // converged: the distance here is within `precision` of the one at the foot;
                // a saddle or a far sheet is no projection (the seed itself is closer)
                if (distance <= seedDistance + precision) return {gp_Pnt2d(u, v), distance};
                break;
            }
            u = nextU;
            v = nextV;
        }
        const gp_Pnt2d foot = fallback_->ValueOfUV(p, precision);
        return {foot, p.Distance(adaptor_.Value(foot.X(), foot.Y()))};
    }

    Foot project(const gp_Pnt& p, double precision) {
        const gp_Pnt2d foot = fallback_->ValueOfUV(p, precision);
        return {foot, p.Distance(adaptor_.Value(foot.X(), foot.Y()))};
    }

    // The global projection meshjudge uses (FreeCAD's Surface.parameter): all extrema of the
    // distance. Slow; for the samples whose seeded projection ends far from the surface, which
    // near a pole can be a false foot on the collapsed row.
    std::optional<Foot> projectGlobally(const gp_Pnt& p) {
        if (!global_) {
            // set up once per surface: the extrema sample the whole surface first
            global_ = std::make_unique<GeomAPI_ProjectPointOnSurf>();
            global_->Init(surface_, uFirst_, uLast_, vFirst_, vLast_);
        }
        global_->Perform(p);
        if (!global_->IsDone() || global_->NbPoints() == 0) return std::nullopt;
        double u = 0, v = 0;
        global_->LowerDistanceParameters(u, v);
        return Foot{gp_Pnt2d(u, v), global_->LowerDistance()};
    }

private:
    Handle(Geom_Surface) surface_;
    std::unique_ptr<GeomAPI_ProjectPointOnSurf> global_;
    GeomAdaptor_Surface adaptor_;
    Handle(ShapeAnalysis_Surface) fallback_;
    double uFirst_ = 0, uLast_ = 0, vFirst_ = 0, vLast_ = 0;
    bool uPeriodic_ = false, vPeriodic_ = false;
};

// A reference for a face that BRepMesh leaves empty (trj7_b1-ec-214.stp's face 311, a B-spline
// face whose wire OpenCASCADE finds invalid): the surface on an n x n grid over the face's
// (u, v) box, n doubled from 32 until every cell's centre is within `deflection` of the mean
// of its corners (at most 512), each cell kept as two triangles where none of its corners
// classifies outside the face; and points along every edge, a step of the box's diagonal over
// 4n in (u, v) at most, for the cover near the boundary, which the kept cells reach to within
// one cell. Its points lie on the exact face as BRepMesh's do: interior ones on the surface,
// the others on the edges.
ReferenceMesh gridReferenceOf(const TopoDS_Face& face, double deflection) {
    ReferenceMesh result;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (!(u1 > u0) || !(v1 > v0) || !std::isfinite(u1 - u0) || !std::isfinite(v1 - v0))
        return result;
    const BRepAdaptor_Surface surface(face);
    int n = 32;
    for (;; n *= 2) {
        double worst = 0;
        for (int i = 0; i < n && worst <= deflection; ++i)
            for (int j = 0; j < n; ++j) {
                const double ua = u0 + (u1 - u0) * i / n, ub = u0 + (u1 - u0) * (i + 1) / n;
                const double va = v0 + (v1 - v0) * j / n, vb = v0 + (v1 - v0) * (j + 1) / n;
                const gp_XYZ mean =
                    0.25 * (surface.Value(ua, va).XYZ() + surface.Value(ub, va).XYZ() +
                            surface.Value(ua, vb).XYZ() + surface.Value(ub, vb).XYZ());
                worst = std::max(
                    worst,
                    (surface.Value(0.5 * (ua + ub), 0.5 * (va + vb)).XYZ() - mean).Modulus());
            }
        if (worst <= deflection || n >= 512) break;
    }
    BRepTopAdaptor_FClass2d classifier(face, Precision::Confusion());
    std::vector<int> index((n + 1) * (n + 1), -1);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const gp_Pnt2d uv(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n);
            if (classifier.Perform(uv) == TopAbs_OUT) continue;
            index[i * (n + 1) + j] = static_cast<int>(result.points.size());
            result.points.push_back(fromOcc(surface.Value(uv.X(), uv.Y())));
            result.parameters.push_back(uv);
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = index[i * (n + 1) + j], b = index[(i + 1) * (n + 1) + j];
            const int c = index[(i + 1) * (n + 1) + j + 1], d = index[i * (n + 1) + j + 1];
            if (a < 0 || b < 0 || c < 0 || d < 0) continue;
            result.triangles.push_back({a, b, c});
            result.triangles.push_back({a, c, d});
        }
    if (result.triangles.empty()) return result;
    const double step = std::hypot(u1 - u0, v1 - v0) / (4.0 * n);
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (BRep_Tool::Degenerated(edge) || !BRep_Tool::IsGeometric(edge)) continue;
        double first = 0, last = 0;
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
        if (pcurve.IsNull() || !(last > first)) continue;
        const double length = pcurve->Value(first).Distance(pcurve->Value(0.5 * (first + last))) +
                              pcurve->Value(0.5 * (first + last)).Distance(pcurve->Value(last));
        const int count = std::clamp(static_cast<int>(std::ceil(4 * length / step)), 16, 4096);
        const BRepAdaptor_Curve curve(edge);
        for (int k = 0; k <= count; ++k)
            result.points.push_back(fromOcc(curve.Value(first + (last - first) * k / count)));
    }
    result.nearBorder = trianglesNearBorder(result.triangles, result.points.size());
    return result;
}

double largestEdgeTolerance(const TopoDS_Face& face) {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(face, TopAbs_EDGE, edges);
    double largest = 0;
    for (int i = 1; i <= edges.Extent(); ++i)
        largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Edge(edges(i))));
    return largest;
}

// A sample of the mesh with its nearest point on the reference mesh, whose distance estimates
// the sample's distance to the trimmed face (within the reference's own deflection) and whose
// (u, v) starts the projection onto the surface.
struct Sample {
    Point3 point;
    double referenceDistance = 0;
    int referenceTriangle = -1;
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
    double surfaceDistance = 0;  // exact, to the untrimmed surface
    gp_Pnt2d foot{0, 0};         // where on the surface
    bool projected = false;      // false when OpenCASCADE could not project it
};

// The face's area (BRepGProp); defined below.
double faceArea(const TopoDS_Face& face);

class FaceMeasurer {
public:
    FaceMeasurer(const TopoDS_Face& face, const Mesh& mesh,
                 const std::vector<std::uint32_t>& triangles, double tolerance)
        : face_(face),
          mesh_(mesh),
          triangles_(triangles),
          tolerance_(tolerance),
          referenceDeflection_(tolerance / referenceDivisor) {}

    FaceDeviation measure() {
        FaceDeviation result;
        result.triangles = triangles_.size();
        result.edgeTolerance = largestEdgeTolerance(face_);
        // BRepMesh refuses a deflection within its confusion distance; a tolerance that small
        // is also below what the B-rep's own points mean
        if (!(referenceDeflection_ > Precision::Confusion())) {
            result.measured = false;
            result.problem =
                "the tolerance is too small to measure: the reference mesh needs "
                "tolerance / " +
                std::to_string(static_cast<int>(referenceDivisor)) +
                " above OpenCASCADE's confusion distance (1e-7)";
            return result;
        }
        if (triangles_.size() > mostTrianglesToMeasure) {
            result.measured = false;
            result.problem = "too large to measure: " + std::to_string(triangles_.size()) +
                             " triangles, more than the " + std::to_string(mostTrianglesToMeasure) +
                             " for which OpenCASCADE's reference mesh of the face is made";
            return result;
        }
        double angle = referenceAngularDeflection(referenceDeflection_);
        if (triangles_.size() > trianglesForAngledReference) angle = coarseReferenceAngle;
        if (triangles_.size() > trianglesForFineReference)
            referenceDeflection_ = tolerance_ / coarseReferenceDivisor;
        ReferenceMesh reference = referenceMeshOf(face_, referenceDeflection_, angle);
        if (reference.triangles.empty()) reference = gridReferenceOf(face_, referenceDeflection_);
        if (reference.triangles.empty() && faceArea(face_) <= tolerance_ * tolerance_) {
            // A face of no area (two edges along one curve: SOD_323.stp of FreeCAD's IDF
            // library, face 16) has nothing to cover; its triangles, a tessellator's sliver
            // along it, are measured against the face itself, which lies along its edges.
            // meshjudge leaves such a face out (no reference mesh), whatever its triangles.
            result.dev = deviationFromFace(result.edgeTolerance);
            return result;
        }
        if (reference.triangles.empty()) {
            result.measured = false;
            result.problem =
                "neither OpenCASCADE's mesh nor a grid on the surface covers the "
                "face, for reference";
            return result;
        }
        result.dev = measureDeviation(reference, result.edgeTolerance);
        result.cover = measureCover(reference, result.edgeTolerance);
        return result;
    }

private:
    // The largest distance from the samples of the face's triangles (FaceSamples) to the exact
    // trimmed face, less the edge tolerance (the slack at a boundary).
    double deviationFromFace(double edgeTolerance) const {
        TrimmedFaceDistance distance(face_);
        const FaceSamples samples(mesh_, triangles_);
        double worst = 0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            const Point3 p = samples[i];
            worst = std::max(worst, distance.distance(gp_Pnt(p.x(), p.y(), p.z())));
        }
        return std::max(0.0, worst - edgeTolerance);
    }

    // The samples of the face's triangles, numbered: the face's vertices once each, then per
    // triangle its edge midpoints, centroid and as many interior points as meshjudge takes for
    // a face of this size. Made on the fly, so that a face of millions of triangles does not
    // hold tens of millions of samples.
    class FaceSamples {
    public:
        FaceSamples(const Mesh& mesh, const std::vector<std::uint32_t>& triangles)
            : mesh_(mesh), triangles_(triangles) {
            vertices_.reserve(triangles.size() * 3);
            for (std::uint32_t t : triangles)
                vertices_.insert(vertices_.end(), mesh.triangles[t].begin(),
                                 mesh.triangles[t].end());
            std::sort(vertices_.begin(), vertices_.end());
            vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
            const std::ptrdiff_t interiorBudget =
                static_cast<std::ptrdiff_t>(samplesPerFaceBudget / triangles.size()) - 7;
            perTriangle_ = 4 + static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
                                   interiorBudget, 0, interiorWeights.size()));
        }

        std::size_t size() const { return vertices_.size() + triangles_.size() * perTriangle_; }

        Point3 operator[](std::size_t index) const {
            if (index < vertices_.size()) return mesh_.positions[vertices_[index]];
            index -= vertices_.size();
            const auto& triangle = mesh_.triangles[triangles_[index / perTriangle_]];
            const Point3& a = mesh_.positions[triangle[0]];
            const Point3& b = mesh_.positions[triangle[1]];
            const Point3& c = mesh_.positions[triangle[2]];
            switch (const std::size_t k = index % perTriangle_) {
                case 0:
                    return (a + b) / 2;
                case 1:
                    return (b + c) / 2;
                case 2:
                    return (c + a) / 2;
                case 3:
                    return (a + b + c) / 3;
                default:
                    return interiorWeights[k - 4][0] * a + interiorWeights[k - 4][1] * b +
                           interiorWeights[k - 4][2] * c;
            }
        }

    private:
        const Mesh& mesh_;
        const std::vector<std::uint32_t>& triangles_;
        std::vector<std::uint32_t> vertices_;
        std::size_t perTriangle_ = 4;
    };

    struct SampleWorker {
        std::unique_ptr<SurfaceProjector> projector;
        double largestSurfaceDistance = 0;
        std::vector<Sample> mayBeOutside;
    };

    // Mesh -> exact face: max over the samples of max(distance to the untrimmed surface,
    // distance to the trimmed face - edge tolerance). Every sample is projected onto the
    // surface by Newton iteration from the (u, v) of its nearest reference point, which lands
    // on the right sheet in a few steps. The trimmed distance equals the surface distance where
    // the projection lies inside the face; only samples near the reference mesh's border can
    // project outside, and only those whose estimate could raise the result are classified
    // and, if outside, measured with the slow exact extrema (trimmedDeviation).
    double measureDeviation(const ReferenceMesh& reference, double edgeTolerance) {
        const TriangleSetDistance referenceSet(reference.points, reference.triangles);
        const FaceSamples samples(mesh_, triangles_);
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face_);
        const double precision = std::max(tolerance_ * 1e-4, Precision::Confusion());
        tbb::enumerable_thread_specific<SampleWorker> workers;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 256),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              SampleWorker& worker = workers.local();
                              if (!worker.projector)
                                  worker.projector = std::make_unique<SurfaceProjector>(surface);
                              int hint = -1;  // consecutive samples lie on one triangle
                              for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                  Sample sample;
                                  sample.point = samples[i];
                                  const auto nearest = referenceSet.nearest(sample.point, hint);
                                  hint = nearest.triangle;
                                  sample.referenceDistance = nearest.distance;
                                  sample.referenceTriangle = nearest.triangle;
                                  sample.weights = nearest.weights;
                                  projectSample(*worker.projector, reference, sample, precision);
                                  worker.largestSurfaceDistance = std::max(
                                      worker.largestSurfaceDistance, sample.surfaceDistance);
                                  if (!sample.projected || sample.referenceTriangle < 0 ||
                                      reference.nearBorder[sample.referenceTriangle])
                                      worker.mayBeOutside.push_back(sample);
                              }
                          });
        double deviation = 0;
        std::vector<Sample> mayBeOutside;
        for (SampleWorker& worker : workers) {
            deviation = std::max(deviation, worker.largestSurfaceDistance);
            mayBeOutside.insert(mayBeOutside.end(), worker.mayBeOutside.begin(),
                                worker.mayBeOutside.end());
        }
        return trimmedDeviation(mayBeOutside, deviation, edgeTolerance);
    }

    void projectSample(SurfaceProjector& projector, const ReferenceMesh& reference, Sample& sample,
                       double precision) const {
        const gp_Pnt p = toOcc(sample.point);
        try {
            OCC_CATCH_SIGNALS
            SurfaceProjector::Foot foot;
            if (!reference.parameters.empty() && sample.referenceTriangle >= 0) {
                const auto& corners = reference.triangles[sample.referenceTriangle];
                gp_XY seed(0, 0);
                for (int k = 0; k < 3; ++k)
                    seed += sample.weights[k] * reference.parameters[corners[k]].XY();
                foot = projector.project(p, gp_Pnt2d(seed), precision);
            } else {
                foot = projector.project(p, precision);
            }
            if (foot.distance > exactCheckFraction * tolerance_)
                if (const auto global = projector.projectGlobally(p);
                    global && global->distance < foot.distance)
                    foot = *global;
            sample.surfaceDistance = foot.distance;
            sample.foot = foot.parameters;
            sample.projected = true;
        } catch (const Standard_Failure&) {
            // meshjudge counts a failed projection as distance 0; the trimmed distance still
            // measures the sample
        }
    }

    // Raises `known` (the largest surface distance) by the samples that project outside the
    // trimmed face. The distance to the reference mesh bounds a sample's trimmed distance
    // within ~reference deflection: samples whose bound cannot beat `known` are skipped; the
    // worst ones (every one whose bound passes half the tolerance, at least 8, at most 4000)
    // are classified and, when outside, measured exactly.
    double trimmedDeviation(std::vector<Sample>& candidates, double known, double edgeTolerance) {
        auto upperEstimate = [&](const Sample& s) {
            return s.referenceDistance + 2 * referenceDeflection_ - edgeTolerance;
        };
        std::erase_if(candidates, [&](const Sample& s) { return upperEstimate(s) <= known; });
        if (candidates.empty()) return known;
        std::sort(candidates.begin(), candidates.end(), [](const Sample& a, const Sample& b) {
            return a.referenceDistance > b.referenceDistance;
        });
        const std::size_t overHalf = static_cast<std::size_t>(std::count_if(
            candidates.begin(), candidates.end(),
            [&](const Sample& s) { return upperEstimate(s) > exactCheckFraction * tolerance_; }));
        const std::size_t exactCount = std::min(
            {candidates.size(), std::max(minimumExactChecks, overHalf), maximumExactChecks});

        // Left unmeasured: samples estimated below half the tolerance keep their surface
        // distance, already in `known` (BRepMesh can miss its deflection severalfold, so an
        // estimate could overstate them); beyond the cap, the estimate less the reference
        // deflection, as meshjudge takes it, lest a face with very many stray samples pass.
        double deviation = known;
        for (std::size_t i = exactCount; i < candidates.size(); ++i)
            if (upperEstimate(candidates[i]) > exactCheckFraction * tolerance_)
                deviation = std::max(deviation, candidates[i].referenceDistance -
                                                    referenceDeflection_ - edgeTolerance);

        // One classifier per thread: BRepTopAdaptor_FClass2d::Perform is const, but it finds
        // each wire's polygon in an NCollection_Sequence whose lookup caches the last node it
        // visited, so threads sharing the classifier of a face with holes could follow
        // another thread's half-written node and crash.
        struct ExactCheck {
            std::unique_ptr<BRepTopAdaptor_FClass2d> classifier;
            std::unique_ptr<TrimmedFaceDistance> distance;
        };
        tbb::enumerable_thread_specific<ExactCheck> checks;
        const double exact = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, exactCount, 8), 0.0,
            [&](const tbb::blocked_range<std::size_t>& range, double largest) {
                ExactCheck& check = checks.local();
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    const Sample& sample = candidates[i];
                    if (sample.projected) {
                        if (!check.classifier)
                            check.classifier = std::make_unique<BRepTopAdaptor_FClass2d>(
                                face_, Precision::Confusion());
                        if (check.classifier->Perform(sample.foot) != TopAbs_OUT)
                            continue;  // inside: the trimmed distance is the surface distance
                    }
                    if (!check.distance)
                        check.distance = std::make_unique<TrimmedFaceDistance>(face_);
                    const double trimmed = check.distance->distance(toOcc(sample.point));
                    largest = std::max(largest, trimmed - edgeTolerance);
                }
                return largest;
            },
            [](double a, double b) { return std::max(a, b); });
        return std::max(deviation, exact);
    }

    // Exact face -> mesh: the reference vertices (points of the exact face) against the face's
    // own triangles.
    double measureCover(const ReferenceMesh& reference, double edgeTolerance) const {
        std::vector<std::uint32_t> used;
        used.reserve(triangles_.size() * 3);
        for (std::uint32_t t : triangles_)
            used.insert(used.end(), mesh_.triangles[t].begin(), mesh_.triangles[t].end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        std::vector<Point3> points;
        points.reserve(used.size());
        for (std::uint32_t index : used) points.push_back(mesh_.positions[index]);
        auto localIndex = [&](std::uint32_t index) {
            return static_cast<int>(std::lower_bound(used.begin(), used.end(), index) -
                                    used.begin());
        };
        std::vector<std::array<int, 3>> triangles;
        triangles.reserve(triangles_.size());
        for (std::uint32_t t : triangles_) {
            const auto& triangle = mesh_.triangles[t];
            triangles.push_back(
                {localIndex(triangle[0]), localIndex(triangle[1]), localIndex(triangle[2])});
        }
        const TriangleSetDistance own(points, triangles);
        const double cover = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, reference.points.size(), 256), 0.0,
            [&](const tbb::blocked_range<std::size_t>& range, double largest) {
                for (std::size_t i = range.begin(); i != range.end(); ++i)
                    largest = std::max(largest, own.nearest(reference.points[i]).distance);
                return largest;
            },
            [](double a, double b) { return std::max(a, b); });
        return std::max(0.0, cover - edgeTolerance);
    }

    const TopoDS_Face& face_;
    const Mesh& mesh_;
    const std::vector<std::uint32_t>& triangles_;
    double tolerance_;
    double referenceDeflection_;
};

// meshjudge's rule: zero area relative to the face's largest triangle (or to 1).
std::size_t countDegenerate(const Mesh& mesh, const std::vector<std::uint32_t>& triangles) {
    std::vector<double> doubleAreas;
    doubleAreas.reserve(triangles.size());
    double largest = 1.0;
    for (std::uint32_t t : triangles) {
        const auto& triangle = mesh.triangles[t];
        const Point3& a = mesh.positions[triangle[0]];
        const double doubleArea =
            (mesh.positions[triangle[1]] - a).cross(mesh.positions[triangle[2]] - a).norm();
        doubleAreas.push_back(doubleArea);
        largest = std::max(largest, doubleArea);
    }
    return static_cast<std::size_t>(
        std::count_if(doubleAreas.begin(), doubleAreas.end(),
                      [&](double doubleArea) { return doubleArea <= 1e-12 * largest; }));
}

struct EdgeCounts {
    std::size_t open = 0, nonManifold = 0, vertices = 0;
};

// Welds positions on a grid of max(tolerance * 1e-3, 1e-9), as meshjudge does, then counts
// the edges used by one triangle (cracks, holes) and by more than two.
EdgeCounts countEdges(const Mesh& mesh, double tolerance) {
    const double quantum = std::max(tolerance * 1e-3, 1e-9);
    using Key = std::array<std::int64_t, 3>;
    std::vector<std::pair<Key, std::uint32_t>> keys(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        Key key;
        for (int axis = 0; axis < 3; ++axis)  // nearbyint: numpy's round half to even
            key[axis] =
                static_cast<std::int64_t>(std::nearbyint(mesh.positions[i][axis] / quantum));
        keys[i] = {key, static_cast<std::uint32_t>(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> welded(mesh.positions.size());
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i > 0 && keys[i].first != keys[i - 1].first) ++next;
        welded[keys[i].second] = next;
    }

    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(mesh.triangles.size() * 3);
    std::vector<std::uint32_t> used;
    used.reserve(mesh.triangles.size() * 3);
    for (const auto& triangle : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = welded[triangle[k]], b = welded[triangle[(k + 1) % 3]];
            used.push_back(a);
            if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(used.begin(), used.end());
    EdgeCounts counts;
    counts.vertices =
        static_cast<std::size_t>(std::unique(used.begin(), used.end()) - used.begin());
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) ++counts.open;
        if (j - i > 2) ++counts.nonManifold;
        i = j;
    }
    return counts;
}

void checkMesh(const Mesh& mesh, int shapeFaces) {
    if (mesh.triangleFaces.size() != mesh.triangles.size())
        throw std::invalid_argument("the mesh has " + std::to_string(mesh.triangles.size()) +
                                    " triangles but " + std::to_string(mesh.triangleFaces.size()) +
                                    " face numbers");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::uint32_t index : mesh.triangles[t])
            if (index >= mesh.positions.size())
                throw std::invalid_argument("triangle " + std::to_string(t) + " uses vertex " +
                                            std::to_string(index) + " of " +
                                            std::to_string(mesh.positions.size()));
        const int face = mesh.triangleFaces[t];
        if (face < 1 || face > shapeFaces)
            throw std::invalid_argument("the mesh names Face" + std::to_string(face) +
                                        " but the model has " + std::to_string(shapeFaces) +
                                        " faces");
    }
    for (const Point3& p : mesh.positions)
        if (!p.allFinite()) throw std::invalid_argument("the mesh has a vertex that is not finite");
}

double faceArea(const TopoDS_Face& face) {
    GProp_GProps properties;
    BRepGProp::SurfaceProperties(face, properties);
    return properties.Mass();
}

}  // namespace

VerificationReport verifyMesh(const TopoDS_Shape& shape, const Mesh& mesh, double tolerance) {
    // a face whose measurement faults in OpenCASCADE is reported, not the end of the process
    const SignalsAsFailures faults;
    const auto start = std::chrono::steady_clock::now();
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw std::invalid_argument("the tolerance must be a positive finite number, not " +
                                    std::to_string(tolerance));
    TopTools_IndexedMapOfShape faceMap;
    TopExp::MapShapes(shape, TopAbs_FACE, faceMap);
    const int shapeFaces = faceMap.Extent();
    checkMesh(mesh, shapeFaces);

    std::vector<std::vector<std::uint32_t>> trianglesOfFace(shapeFaces + 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        trianglesOfFace[mesh.triangleFaces[t]].push_back(static_cast<std::uint32_t>(t));

    std::vector<std::optional<FaceDeviation>> deviations(shapeFaces + 1);
    std::vector<char> missing(shapeFaces + 1, 0);
    std::vector<std::size_t> degenerate(shapeFaces + 1, 0);
    tbb::parallel_for(
        tbb::blocked_range<int>(1, shapeFaces + 1, 1), [&](const tbb::blocked_range<int>& range) {
            for (int f = range.begin(); f != range.end(); ++f) {
                const TopoDS_Face& face = TopoDS::Face(faceMap(f));
                const std::vector<std::uint32_t>& triangles = trianglesOfFace[f];
                if (triangles.empty()) {
                    try {
                        OCC_CATCH_SIGNALS
                        missing[f] = faceArea(face) > tolerance * tolerance;
                    } catch (const Standard_Failure&) {
                        missing[f] = 1;  // a face whose area cannot be measured is not empty
                    }
                    continue;
                }
                degenerate[f] = countDegenerate(mesh, triangles);
                FaceDeviation deviation;
                try {
                    OCC_CATCH_SIGNALS
                    deviation = FaceMeasurer(face, mesh, triangles, tolerance).measure();
                } catch (const Standard_Failure& failure) {
                    deviation.measured = false;
                    deviation.problem =
                        std::string("OpenCASCADE failed: ") + failure.GetMessageString();
                } catch (const std::exception& failure) {
                    deviation.measured = false;
                    deviation.problem = failure.what();
                }
                deviation.face = f;
                deviation.triangles = triangles.size();
                deviations[f] = deviation;
            }
        });

    VerificationReport report;
    report.tolerance = tolerance;
    report.shapeFaces = shapeFaces;
    report.triangles = mesh.triangles.size();
    for (int f = 1; f <= shapeFaces; ++f) {
        if (missing[f]) report.facesMissing.push_back(f);
        report.degenerateTriangles += degenerate[f];
        if (!deviations[f]) continue;
        const FaceDeviation& deviation = *deviations[f];
        report.faces.push_back(deviation);
        if (!deviation.measured) {
            report.facesUnmeasured.push_back(f);
            continue;
        }
        report.maxDev = std::max(report.maxDev, deviation.dev);
        report.maxCover = std::max(report.maxCover, deviation.cover);
        if (deviation.dev > tolerance || deviation.cover > tolerance)
            report.facesOverTolerance.push_back(f);
    }
    const EdgeCounts edges = countEdges(mesh, tolerance);
    report.openEdges = edges.open;
    report.nonManifoldEdges = edges.nonManifold;
    report.vertices = edges.vertices;
    report.pass = report.facesOverTolerance.empty() && report.facesMissing.empty() &&
                  report.facesUnmeasured.empty();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace nurbslod::occ
