#include "occ/ModelImporter.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2dConvert_ApproxCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <limits>
#include <optional>

#include "occ/ClosedSurfaceUnwrapper.hpp"
#include "occ/FaceSewing.hpp"
#include "occ/PcurveFromEdgeCurve.hpp"

namespace nurbslod::occ {

namespace {

// Sewing tolerance as a fraction of the bounding-box diagonal: copies of one edge in a file
// written without topology coincide to rounding, far closer than this, while distinct edges of
// a real part are farther apart.
constexpr double kSewingTolerance = 1e-6;
// The same fraction bounds how far a pcurve may stray from its edge before it is remade: a
// hundredth of the finest tolerance (relative 1e-4) that the benchmarks ask for.
constexpr double kPcurveAccuracy = 1e-6;

}  // namespace

BSplineSurface toBSplineSurface(const Handle(Geom_BSplineSurface) & s) {
    std::vector<double> knotsU, knotsV;
    TColStd_Array1OfReal ku(1, s->NbUPoles() + s->UDegree() + 1);
    TColStd_Array1OfReal kv(1, s->NbVPoles() + s->VDegree() + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    for (int i = ku.Lower(); i <= ku.Upper(); ++i) knotsU.push_back(ku(i));
    for (int i = kv.Lower(); i <= kv.Upper(); ++i) knotsV.push_back(kv(i));
    const int nu = s->NbUPoles(), nv = s->NbVPoles();
    std::vector<HomogeneousPoint3> poles(static_cast<size_t>(nu * nv));
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const gp_Pnt p = s->Pole(i + 1, j + 1);
            const double w = s->Weight(i + 1, j + 1);
            poles[i * nv + j] = HomogeneousPoint3(w * p.X(), w * p.Y(), w * p.Z(), w);
        }
    return BSplineSurface(KnotVector(s->UDegree(), std::move(knotsU)),
                          KnotVector(s->VDegree(), std::move(knotsV)), nu, nv, std::move(poles));
}

namespace {

BSplineCurve2d toCurve(const Handle(Geom2d_BSplineCurve) & c) {
    std::vector<double> knots;
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    for (int i = k.Lower(); i <= k.Upper(); ++i) knots.push_back(k(i));
    std::vector<HomogeneousPoint2> poles;
    for (int i = 1; i <= c->NbPoles(); ++i) {
        const gp_Pnt2d p = c->Pole(i);
        const double w = c->Weight(i);
        poles.emplace_back(w * p.X(), w * p.Y(), w);
    }
    return BSplineCurve2d(KnotVector(c->Degree(), std::move(knots)), std::move(poles));
}

// The pcurve over [first, last] as a B-spline with the SAME parameter as the edge: the edge
// parameter is what every face of the edge shares. Lines, Beziers and B-splines convert
// exactly; conics would be reparameterised by an exact conversion, so they are approximated
// in their own parameter instead (to far below any display or export tolerance).
Handle(Geom2d_BSplineCurve)
    pcurveAsBSpline(const Handle(Geom2d_Curve) & curve, double first, double last) {
    Handle(Geom2d_Curve) basis = curve;
    while (auto trimmed = Handle(Geom2d_TrimmedCurve)::DownCast(basis))
        basis = trimmed->BasisCurve();
    Handle(Geom2d_BSplineCurve) result;
    if (auto bspline = Handle(Geom2d_BSplineCurve)::DownCast(basis)) {
        result = Handle(Geom2d_BSplineCurve)::DownCast(bspline->Copy());
        if (result->IsPeriodic()) result->SetNotPeriodic();
    } else if (basis->IsKind(STANDARD_TYPE(Geom2d_Line)) ||
               basis->IsKind(STANDARD_TYPE(Geom2d_BezierCurve))) {
        result = Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(basis, first, last));
    } else {
        Handle(Geom2d_TrimmedCurve) piece = new Geom2d_TrimmedCurve(basis, first, last);
        Geom2dConvert_ApproxCurve approx(
            piece, 1e-9 * std::max(1.0, piece->Value(first).XY().Modulus()), GeomAbs_C2, 200, 9);
        if (!approx.HasResult()) throw Standard_Failure("a trimming curve could not be converted");
        result = approx.Curve();
    }
    return result;
}

// The face's surface under any rectangular trims (null for a face without geometry), and its
// location.
Handle(Geom_Surface) untrimmedSurface(const TopoDS_Face& face, TopLoc_Location& location) {
    Handle(Geom_Surface) surface = BRep_Tool::Surface(face, location);
    while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface))
        surface = trimmed->BasisSurface();
    return surface;
}

}  // namespace

Handle(Geom_BSplineSurface) faceSurfaceAsBSpline(const TopoDS_Face& face) {
    TopLoc_Location location;
    const Handle(Geom_Surface) basis = untrimmedSurface(face, location);
    if (basis.IsNull()) throw Standard_Failure("the face has no surface");
    Handle(Geom_BSplineSurface) bspline = Handle(Geom_BSplineSurface)::DownCast(basis);
    if (bspline.IsNull()) {
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        bspline = GeomConvert::SurfaceToBSplineSurface(
            new Geom_RectangularTrimmedSurface(basis, u0, u1, v0, v1));
    } else {
        bspline = Handle(Geom_BSplineSurface)::DownCast(bspline->Copy());
    }
    // Unclamped (periodic) knots would break the Bezier extraction; clamp them. The parameter
    // does not change, so the pcurves stay valid.
    if (bspline->IsUPeriodic()) bspline->SetUNotPeriodic();
    if (bspline->IsVPeriodic()) bspline->SetVNotPeriodic();
    if (!location.IsIdentity()) bspline->Transform(location.Transformation());
    return bspline;
}

namespace {

// True for a face whose surface becomes a B-spline of the same parameter (a B-spline or a
// plane) and whose edges' curves do too (lines, B-splines, Beziers): neither its pcurves nor
// the parameter its edges share with their other faces change in a conversion. A circle's
// B-spline form has another parameter, and the faces of an edge must agree on its parameter.
bool keepsParameterAsBSpline(const TopoDS_Face& face) {
    TopLoc_Location location;
    const Handle(Geom_Surface) surface = untrimmedSurface(face, location);
    if (surface.IsNull() || !(surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) ||
                              surface->IsKind(STANDARD_TYPE(Geom_Plane))))
        return false;
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        double first = 0, last = 0;
        Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        while (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(curve))
            curve = trimmed->BasisCurve();
        if (curve.IsNull() || !(curve->IsKind(STANDARD_TYPE(Geom_Line)) ||
                                curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) ||
                                curve->IsKind(STANDARD_TYPE(Geom_BezierCurve))))
            return false;
    }
    return true;
}

TrimLoop importLoop(const TopoDS_Wire& wire, const TopoDS_Face& face,
                    const TopTools_DataMapOfShapeInteger& edgeIndex,
                    std::vector<TopoDS_Edge>& curveEdges) {
    TrimLoop loop;
    std::vector<TopoDS_Edge> ordered;
    for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
        ordered.push_back(it.Current());
    // The wire explorer drops edges of sloppy wires it cannot chain; fall back to file order.
    size_t count = 0;
    for (TopExp_Explorer it(wire, TopAbs_EDGE); it.More(); it.Next()) ++count;
    if (ordered.size() != count) {
        ordered.clear();
        for (TopExp_Explorer it(wire, TopAbs_EDGE); it.More(); it.Next())
            ordered.push_back(TopoDS::Edge(it.Current()));
    }
    for (const TopoDS_Edge& edge : ordered) {
        TrimCurve curve;
        double first = 0, last = 0;
        Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
        if (pcurve.IsNull()) throw Standard_Failure("an edge has no curve on the face");
        if (!(last > first) || !std::isfinite(first) || !std::isfinite(last))
            throw Standard_Failure("an edge has an empty or infinite parameter range");
        curve.pcurve = toCurve(pcurveAsBSpline(pcurve, first, last));
        curve.first = first;
        curve.last = last;
        curve.edge = edgeIndex.IsBound(edge) ? edgeIndex.Find(edge) : -1;
        curve.reversed = edge.Orientation() == TopAbs_REVERSED;
        curve.seam = BRep_Tool::IsClosed(edge, face);
        curve.degenerated = BRep_Tool::Degenerated(edge);
        loop.curves.push_back(std::move(curve));
        curveEdges.push_back(edge);
    }
    return loop;
}

// A box around the loops' pcurves over their edge ranges: the control points whose basis
// functions reach into [first, last] (convex hull property, weights > 0).
std::pair<Point2, Point2> pcurveBounds(const std::vector<TrimLoop>& loops) {
    Point2 low = Point2::Constant(std::numeric_limits<double>::max()), high = -low;
    for (const auto& loop : loops)
        for (const auto& curve : loop.curves) {
            const auto& knots = curve.pcurve.knots();
            const auto& poles = curve.pcurve.poles();
            if (curve.pcurve.problem()) continue;
            const int from = knots.findSpan(curve.first) - knots.degree();
            const int to = knots.findSpan(curve.last);
            for (int i = std::max(0, from); i <= to && i < static_cast<int>(poles.size()); ++i) {
                const Point2 p = poles[i].head<2>() / poles[i][2];
                low = low.cwiseMin(p);
                high = high.cwiseMax(p);
            }
        }
    return {low, high};
}

// pcurveAccuracy: a pcurve that strays farther than this from its edge's 3D curve is remade
// from the 3D curve (see pcurveFromEdgeCurve).
TrimmedSurface importFace(const TopoDS_Face& face, int index,
                          const TopTools_DataMapOfShapeInteger& edgeIndex, double pcurveAccuracy) {
    TrimmedSurface result;
    result.faceIndex = index;
    result.reversed = face.Orientation() == TopAbs_REVERSED;
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    std::vector<std::vector<TopoDS_Edge>> curveEdges;
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) {
        const TopoDS_Wire wire = TopoDS::Wire(it.Current());
        std::vector<TopoDS_Edge> loopEdges;
        TrimLoop loop = importLoop(wire, face, edgeIndex, loopEdges);
        loop.outer = wire.IsSame(outer);
        if (!loop.curves.empty()) {
            result.loops.push_back(std::move(loop));
            curveEdges.push_back(std::move(loopEdges));
        }
    }
    if (result.loops.empty()) throw Standard_Failure("the face has no trimming loop");
    // The pcurves may wind over more than the one turn a closed surface's NURBS form covers
    // (a thread on a cylinder): the surface is unwrapped to cover them, and the pcurves are
    // carried onto it.
    const Handle(Geom_BSplineSurface) surface = faceSurfaceAsBSpline(face);
    const auto [low, high] = pcurveBounds(result.loops);
    const Handle(Geom_BSplineSurface) unwrapped =
        unwrapClosedSurface(surface, low.x(), high.x(), low.y(), high.y());
    for (size_t l = 0; l < result.loops.size(); ++l)
        for (size_t c = 0; c < result.loops[l].curves.size(); ++c) {
            TrimCurve& curve = result.loops[l].curves[c];
            if (curve.degenerated) continue;  // a point in 3D: its (u, v) line stays
            double first = 0, last = 0;
            const Handle(Geom2d_Curve) pcurve =
                BRep_Tool::CurveOnSurface(curveEdges[l][c], face, first, last);
            if (unwrapped == surface && pcurveDeviation(curveEdges[l][c], surface, pcurve,
                                                        curve.first, curve.last) <= pcurveAccuracy)
                continue;
            const Handle(Geom2d_BSplineCurve) remade = pcurveFromEdgeCurve(
                curveEdges[l][c], unwrapped, pcurve, curve.first, curve.last, pcurveAccuracy);
            if (!remade.IsNull()) curve.pcurve = toCurve(remade);
        }
    result.surface = toBSplineSurface(unwrapped);
    return result;
}

}  // namespace

Model importModel(const TopoDS_Shape& original) {
    Model model;
    TopTools_IndexedMapOfShape originalFaces;
    TopExp::MapShapes(original, TopAbs_FACE, originalFaces);
    Bnd_Box box;
    BRepBndLib::Add(original, box);
    if (!box.IsVoid()) {
        box.SetGap(0.0);
        model.boundingBoxDiagonal = std::sqrt(box.SquareExtent());
    }

    // Loose faces (no shared edges in the file) are sewn where their edges coincide to far
    // below any tolerance a user asks for, so that the mesh closes across them.
    const SewnShape sewn = sewFaces(original, kSewingTolerance * model.boundingBoxDiagonal);

    // Faces on a B-spline surface or a plane are taken as they are: faceSurfaceAsBSpline
    // gives them a B-spline surface of the same parameter, so their pcurves stay valid.
    // BRepBuilderAPI_NurbsConvert would copy them and project every pcurve of theirs onto the
    // copy again (ProjLib_ComputeApproxOnPolarSurface), which took most of the import time of
    // B-spline models (about 60% of trj7's). The other faces (cylinders, cones, spheres, tori,
    // revolutions, offsets) change parameter with their surface and are converted together, so
    // that they share their converted edges; a converted edge keeps the index of the edge it
    // came from, which is what the faces of an edge share.
    TopTools_IndexedMapOfShape edges, vertices;
    TopExp::MapShapes(sewn.shape, TopAbs_EDGE, edges);
    TopExp::MapShapes(sewn.shape, TopAbs_VERTEX, vertices);
    TopTools_DataMapOfShapeInteger edgeIndex;
    for (int k = 1; k <= edges.Extent(); ++k) edgeIndex.Bind(edges(k), k - 1);

    std::vector<bool> keeps(sewn.faces.size());
    TopoDS_Compound toConvert;
    BRep_Builder builder;
    builder.MakeCompound(toConvert);
    bool anyToConvert = false;
    for (size_t k = 0; k < sewn.faces.size(); ++k) {
        keeps[k] = keepsParameterAsBSpline(sewn.faces[k]);
        if (!keeps[k]) builder.Add(toConvert, sewn.faces[k]), anyToConvert = true;
    }
    std::optional<BRepBuilderAPI_NurbsConvert> converter;
    if (anyToConvert) {
        try {
            converter.emplace(toConvert, Standard_False);
            if (!converter->IsDone()) converter.reset();
        } catch (const Standard_Failure&) {
            converter.reset();
        }
        if (converter) {
            TopTools_IndexedMapOfShape convertedEdges;
            TopExp::MapShapes(toConvert, TopAbs_EDGE, convertedEdges);
            for (int k = 1; k <= convertedEdges.Extent(); ++k)
                if (edgeIndex.IsBound(convertedEdges(k)))
                    edgeIndex.Bind(converter->ModifiedShape(convertedEdges(k)),
                                   edgeIndex.Find(convertedEdges(k)));
        }
    }

    model.faces.resize(originalFaces.Extent());
    for (int k = 1; k <= originalFaces.Extent(); ++k) {
        const TopoDS_Face originalFace = TopoDS::Face(originalFaces(k));
        try {
            TopoDS_Face face;
            if (keeps[k - 1]) {
                face = sewn.faces[k - 1];
            } else if (converter) {
                face = TopoDS::Face(converter->ModifiedShape(sewn.faces[k - 1]));
            } else {
                // the faces together failed to convert: this one alone, its edges its own
                BRepBuilderAPI_NurbsConvert single(sewn.faces[k - 1], Standard_False);
                face = TopoDS::Face(single.Shape());
            }
            // the converted face comes back FORWARD; the orientation (which side is outside)
            // is the original face's
            face.Orientation(originalFace.Orientation());
            model.faces[k - 1] =
                importFace(face, k, edgeIndex, kPcurveAccuracy * model.boundingBoxDiagonal);
        } catch (const Standard_Failure& failure) {
            model.faces[k - 1].faceIndex = k;
            model.faces[k - 1].error = std::string("import failed: ") + failure.GetMessageString();
        }
        if (model.faces[k - 1].error.empty())
            if (auto problem = model.faces[k - 1].surface.problem())
                model.faces[k - 1].error = "invalid surface: " + *problem;
    }

    model.vertices.resize(vertices.Extent());
    for (int k = 1; k <= vertices.Extent(); ++k) {
        const TopoDS_Vertex& vertex = TopoDS::Vertex(vertices(k));
        const gp_Pnt p = BRep_Tool::Pnt(vertex);
        model.vertices[k - 1] = {Point3(p.X(), p.Y(), p.Z()), BRep_Tool::Tolerance(vertex)};
    }
    model.edges.resize(edges.Extent());
    for (int k = 1; k <= edges.Extent(); ++k) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges(k));
        TopoDS_Vertex first, last;
        TopExp::Vertices(edge, first, last);
        ModelEdge& e = model.edges[k - 1];
        e.firstVertex = first.IsNull() ? -1 : vertices.FindIndex(first) - 1;
        e.lastVertex = last.IsNull() ? -1 : vertices.FindIndex(last) - 1;
        e.tolerance = BRep_Tool::Tolerance(edge);
        e.degenerated = BRep_Tool::Degenerated(edge);
    }

    return model;
}

}  // namespace nurbslod::occ
