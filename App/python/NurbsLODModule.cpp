// The Python module NurbsLOD: the macro API of the workbench.
//
// FreeCAD ships no C++ headers, so a FreeCAD shape crosses into C++ as the BREP text of
// shape.exportBrepToString(), which carries it exactly (DESIGN.md). Everything after that is
// plain C++ run without the GIL, so other Python threads (a macro's worker thread, FreeCAD's
// own) keep running while a large model is tessellated.
//
// Nothing here may crash FreeCAD: a crash loses the user's unsaved work. Every failure,
// including OpenCASCADE's own exceptions (which do not derive from std::exception), becomes a
// Python exception with a message that says what was wrong.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "CallerThreadProgress.hpp"
#include "io/MeshWriter.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/AnalysisMesh.hpp"
#include "tessellate/ModelTessellator.hpp"
#include "tessellate/ToleranceRequest.hpp"

namespace py = pybind11;

namespace nurbslod::python {
namespace {

// Where the model comes from. Read while the GIL is held (a FreeCAD shape is a Python
// object); turned into a TopoDS_Shape after the GIL is released.
struct ShapeSource {
    bool isPath = false;
    std::string text;  // the file path, or the BREP text of a FreeCAD shape
};

std::string typeName(const py::handle& object) {
    return py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
}

ShapeSource shapeSource(const py::object& shape) {
    if (py::isinstance<py::str>(shape)) {
        return {true, shape.cast<std::string>()};
    }
    if (py::hasattr(shape, "__fspath__")) {  // pathlib.Path and friends
        return {true, py::module_::import("os").attr("fspath")(shape).cast<std::string>()};
    }
    if (py::hasattr(shape, "exportBrepToString")) {  // Part.Shape, Part.Face, Part.Solid...
        return {false, shape.attr("exportBrepToString")().cast<std::string>()};
    }
    // A document object (Part::Feature): tessellate what it shows.
    if (py::hasattr(shape, "Shape") && py::hasattr(shape.attr("Shape"), "exportBrepToString")) {
        return {false, shape.attr("Shape").attr("exportBrepToString")().cast<std::string>()};
    }
    throw py::type_error("NurbsLOD: expected a Part.Shape, a Part object or a file path, got " +
                         typeName(shape));
}

// The caller's tolerance, checked before any work so that a typo fails at once (pybind11
// turns std::invalid_argument into ValueError).
ToleranceRequest toleranceRequest(std::optional<double> tolerance, std::optional<double> relative) {
    const ToleranceRequest request{tolerance, relative};
    try {
        checkToleranceRequest(request);
    } catch (const std::invalid_argument& error) {
        throw py::value_error(std::string("NurbsLOD: ") + error.what());
    }
    return request;
}

ErrorMode errorMode(const std::string& mode) {
    if (mode == "guaranteed") {
        return ErrorMode::Guaranteed;
    }
    if (mode == "approximate") {
        return ErrorMode::Approximate;
    }
    throw py::value_error("NurbsLOD: mode must be \"guaranteed\" or \"approximate\", got \"" +
                          mode + "\"");
}

const char* modeName(ErrorMode mode) {
    return mode == ErrorMode::Guaranteed ? "guaranteed" : "approximate";
}

int threadCount(int threads) {
    if (threads < 0) {
        throw py::value_error("NurbsLOD: threads must be 0 (all cores) or a positive count, got " +
                              std::to_string(threads));
    }
    return threads;
}

using Clock = std::chrono::steady_clock;

// Seconds spent reading the shape and turning its faces into trimmed NURBS (the summary's
// read_seconds and import_seconds).
struct SourceSeconds {
    double read = 0, import = 0;
};

// Runs without the GIL: reading and importing are pure C++.
Model importSource(const ShapeSource& source, int threads, SourceSeconds& seconds,
                   const std::function<void(std::size_t, std::size_t)>& progress = nullptr) {
    const Clock::time_point start = Clock::now();
    const TopoDS_Shape shape =
        source.isPath ? occ::readShape(source.text) : occ::shapeFromBrepString(source.text);
    const Clock::time_point read = Clock::now();
    Model model = occ::importModel(shape, threads, progress);
    seconds.read = std::chrono::duration<double>(read - start).count();
    seconds.import = std::chrono::duration<double>(Clock::now() - read).count();
    if (model.faces.empty()) {
        throw std::invalid_argument("NurbsLOD: the shape has no faces to tessellate");
    }
    return model;
}

double absoluteTolerance(const Model& model, const ToleranceRequest& request) {
    try {
        return resolveTolerance(request, model.boundingBoxDiagonal);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("NurbsLOD: ") + error.what());
    }
}

// tessellateModel, its refusals (a tolerance finer than the model can take) named as the
// module's own
TessellationResult tessellateOrRefuse(const Model& model, const TessellationOptions& options) {
    try {
        return tessellateModel(model, options);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("NurbsLOD: ") + error.what());
    }
}

// Runs without the GIL: reading, importing and tessellating are pure C++.
TessellationResult tessellateSource(
    const ShapeSource& source, const ToleranceRequest& request, TessellationOptions options,
    SourceSeconds& seconds,
    const std::function<void(std::size_t, std::size_t)>& importProgress = nullptr) {
    const Model model = importSource(source, options.threads, seconds, importProgress);
    options.tolerance = absoluteTolerance(model, request);
    return tessellateOrRefuse(model, options);
}

struct Call {
    Clock::time_point start = Clock::now();  // for the summary's total_seconds
    ShapeSource source;
    ToleranceRequest tolerance;
    TessellationOptions options;
    mutable SourceSeconds sourceSeconds;  // filled in by run()
    py::object progress = py::none();     // progress(stage, done, total), or None
};

// Checks every argument before the (possibly long) work starts.
Call parseCall(const py::object& shape, std::optional<double> tolerance,
               std::optional<double> relative, const std::string& mode, int threads,
               const py::object& progress, bool compact = false) {
    Call call;
    if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
        throw py::type_error("NurbsLOD: progress must be None or a callable (stage, done, total)");
    call.progress = progress;
    call.tolerance = toleranceRequest(tolerance, relative);
    call.options.mode = errorMode(mode);
    call.options.threads = threadCount(threads);
    call.options.compact = compact;
    call.source = shapeSource(shape);
    return call;
}

TessellationResult run(const Call& call) {
    if (call.progress.is_none()) {
        py::gil_scoped_release release;
        return tessellateSource(call.source, call.tolerance, call.options, call.sourceSeconds);
    }
    TessellationResult result;
    runReportingProgress(
        [&](JobProgress& progress) {
            TessellationOptions options = call.options;
            options.progress = progress.stage(JobProgress::Tessellate);
            result = tessellateSource(call.source, call.tolerance, options, call.sourceSeconds,
                                      progress.stage(JobProgress::Import));
        },
        call.progress);
    return result;
}

// The summary has the keys of the command line's JSON summary, so scripts can use either.
// total_seconds counts everything from the call on; seconds only the tessellation; read_seconds
// and import_seconds the reading of the shape and its faces' conversion into trimmed NURBS.
py::dict summaryDict(const TessellationResult& result, const Call& call,
                     const std::optional<std::string>& output = std::nullopt) {
    auto faceList = [](const std::vector<FaceFailure>& faces) {
        py::list list;
        for (const FaceFailure& face : faces) {
            py::dict entry;
            entry["face"] = face.face;
            entry["reason"] = face.reason;
            list.append(entry);
        }
        return list;
    };
    py::dict summary;
    summary["faces"] = result.faces;
    summary["triangles"] = result.mesh.triangles.size();
    summary["vertices"] = result.mesh.positions.size();
    summary["seconds"] = result.seconds;
    summary["total_seconds"] = std::chrono::duration<double>(Clock::now() - call.start).count();
    summary["read_seconds"] = call.sourceSeconds.read;
    summary["import_seconds"] = call.sourceSeconds.import;
    summary["tolerance"] = result.tolerance;
    summary["mode"] = modeName(call.options.mode);
    if (output) {
        summary["output"] = *output;
    }
    summary["faces_warned"] = faceList(result.warnings);
    summary["faces_failed"] = faceList(result.failures);
    return summary;
}

py::array_t<double> vectorArray(const std::vector<Vector3>& vectors) {
    py::array_t<double> array({static_cast<py::ssize_t>(vectors.size()), py::ssize_t{3}});
    auto view = array.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < view.shape(0); ++i) {
        for (py::ssize_t j = 0; j < 3; ++j) {
            view(i, j) = vectors[static_cast<std::size_t>(i)][j];
        }
    }
    return array;
}

py::array_t<std::uint32_t> indexArray(const std::vector<std::array<std::uint32_t, 3>>& indices) {
    py::array_t<std::uint32_t> array({static_cast<py::ssize_t>(indices.size()), py::ssize_t{3}});
    auto view = array.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < view.shape(0); ++i) {
        for (py::ssize_t j = 0; j < 3; ++j) {
            view(i, j) = indices[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        }
    }
    return array;
}

py::dict tessellate(const py::object& shape, std::optional<double> tolerance,
                    std::optional<double> relative, const std::string& mode, int threads,
                    const py::object& progress, bool compact) {
    const Call call = parseCall(shape, tolerance, relative, mode, threads, progress, compact);
    const TessellationResult result = run(call);
    const Mesh& mesh = result.mesh;
    py::dict out;
    out["points"] = vectorArray(mesh.positions);
    out["normals"] = vectorArray(mesh.normals);
    out["triangles"] = indexArray(mesh.triangles);
    out["triangle_normals"] = indexArray(mesh.triangleNormals);
    out["face_ids"] = py::array_t<std::int32_t>(static_cast<py::ssize_t>(mesh.triangleFaces.size()),
                                                mesh.triangleFaces.data());
    out["summary"] = summaryDict(result, call);
    return out;
}

py::dict exportMesh(const py::object& shape, const py::object& path,
                    std::optional<double> tolerance, std::optional<double> relative,
                    const std::string& mode, int threads, const py::object& progress,
                    bool compact) {
    const Call call = parseCall(shape, tolerance, relative, mode, threads, progress, compact);
    const std::string outPath = py::module_::import("os").attr("fspath")(path).cast<std::string>();
    const TessellationResult result = run(call);
    {
        py::gil_scoped_release release;
        writeMesh(result.mesh, outPath);
    }
    return summaryDict(result, call, outPath);
}

py::object toMesh(const py::object& shape, std::optional<double> tolerance,
                  std::optional<double> relative, const std::string& mode, int threads,
                  const py::object& progress, bool compact) {
    // Imported first: outside FreeCAD there is no point tessellating.
    py::module_ meshModule;
    py::module_ freecad;
    try {
        meshModule = py::module_::import("Mesh");
        freecad = py::module_::import("FreeCAD");
    } catch (py::error_already_set& error) {
        throw py::import_error(std::string("NurbsLOD.to_mesh needs FreeCAD's Mesh module: ") +
                               error.what());
    }
    const Call call = parseCall(shape, tolerance, relative, mode, threads, progress, compact);
    const TessellationResult result = run(call);
    const Mesh& mesh = result.mesh;

    // Mesh.addFacets((points, facets)) wants FreeCAD.Vector points and tuple facets: FreeCAD
    // 0.20 crashes when the points are plain tuples.
    const py::object vectorType = freecad.attr("Vector");
    py::list points(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Point3& p = mesh.positions[i];
        points[i] = vectorType(p.x(), p.y(), p.z());
    }
    py::list facets(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        facets[i] = py::make_tuple(t[0], t[1], t[2]);
    }
    py::object freecadMesh = meshModule.attr("Mesh")();
    freecadMesh.attr("addFacets")(py::make_tuple(points, facets));
    return freecadMesh;
}

py::array_t<double> scalarArray(const std::vector<double>& values) {
    return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::array_t<double> parameterArray(const std::vector<Point2>& parameters) {
    py::array_t<double> array({static_cast<py::ssize_t>(parameters.size()), py::ssize_t{2}});
    auto view = array.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < view.shape(0); ++i) {
        view(i, 0) = parameters[static_cast<std::size_t>(i)].x();
        view(i, 1) = parameters[static_cast<std::size_t>(i)].y();
    }
    return array;
}

py::dict analysisMeshOf(const py::object& shape, std::optional<double> tolerance,
                        std::optional<double> relative, const std::string& mode, int threads) {
    const Call call = parseCall(shape, tolerance, relative, mode, threads, py::none());
    TessellationResult result;
    AnalysisMesh analysis;
    {
        py::gil_scoped_release release;
        const Model model = importSource(call.source, call.options.threads, call.sourceSeconds);
        TessellationOptions options = call.options;
        options.tolerance = absoluteTolerance(model, call.tolerance);
        // The overlays interpolate per-vertex normals and curvatures across each triangle, at
        // equal parameters, as the display's LOD does: its cells take the bound at equal
        // parameters, not the distance bounds (flat cells, the even-speed parameter), under
        // which a cell of a G2 joint's patch grew wide enough to kink its zebra stripes by 15
        // degrees. For the same reason they keep the halvings where columns are cut across
        // (the G2 joint's zebra stripes kinked by 11.7 degrees with even columns there), and
        // the paper's cuts through the farthest net point (13.2 degrees with middle halvings).
        options.flatCellsByDistance = false;
        options.evenColumnsCutAcross = false;
        options.middleSplits = false;
        options.openPointsBoundedBySurface = false;
        result = tessellateOrRefuse(model, options);
        analysis = analysisMesh(model, result.mesh);
    }
    py::dict out;
    out["points"] = vectorArray(analysis.points);
    out["normals"] = vectorArray(analysis.normals);
    out["parameters"] = parameterArray(analysis.parameters);
    out["gaussian"] = scalarArray(analysis.gaussian);
    out["mean"] = scalarArray(analysis.mean);
    out["minimum"] = scalarArray(analysis.minimum);
    out["maximum"] = scalarArray(analysis.maximum);
    out["triangles"] = indexArray(analysis.triangles);
    out["face_ids"] = py::array_t<std::int32_t>(
        static_cast<py::ssize_t>(analysis.triangleFaces.size()), analysis.triangleFaces.data());
    py::dict summary = summaryDict(result, call);
    summary["vertices"] = analysis.points.size();
    summary["singular_vertices"] = analysis.singularVertices;
    out["summary"] = summary;
    return out;
}

void translateOpenCascadeFailures() {
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) {
                std::rethrow_exception(error);
            }
        } catch (const Standard_Failure& failure) {
            const std::string message = std::string("NurbsLOD: OpenCASCADE failed: ") +
                                        failure.DynamicType()->Name() + ": " +
                                        failure.GetMessageString();
            PyErr_SetString(PyExc_RuntimeError, message.c_str());
        }
    });
}

}  // namespace
}  // namespace nurbslod::python

PYBIND11_MODULE(NurbsLOD, m) {
    using namespace nurbslod::python;
    m.doc() =
        "NurbsLOD: tessellation of trimmed NURBS B-rep models with a guaranteed error.\n\n"
        "shape arguments take a Part.Shape, a document object with a Shape, or a path to a\n"
        "STEP, IGES or BREP file. Give either tolerance (absolute, model units) or relative\n"
        "(fraction of the bounding box diagonal); with neither, relative=1e-3.";

    // the limits tessellate() refuses beyond, for callers that check first (the workbench's
    // display keeps FreeCAD's own mesher to the same floor)
    m.attr("SMALLEST_MODEL") = nurbslod::kSmallestModel;
    m.attr("FINEST_RELATIVE_TOLERANCE") = nurbslod::kFinestRelativeTolerance;

    py::register_exception<nurbslod::occ::ModelReadError>(m, "ReadError", PyExc_ValueError);
    translateOpenCascadeFailures();

    m.def("tessellate", &tessellate, py::arg("shape"), py::arg("tolerance") = py::none(),
          py::arg("relative") = py::none(), py::arg("mode") = "guaranteed", py::arg("threads") = 0,
          py::arg("progress") = py::none(), py::arg("compact") = false,
          R"(Tessellates every face of the shape within the tolerance.

mode: "guaranteed" (the mesh never deviates more than the tolerance) or "approximate"
(the paper's approximate error: fewer triangles). threads: 0 uses all cores.
compact: guaranteed mode only; removes the inner points whose fans can be re-triangulated
with each triangle bounded within the tolerance: the same guarantee, fewer triangles
(0.92x over the project's benchmark models, down to 0.2x on free-form faces), about
1.8x the tessellation time.
progress: None, or a callable progress(stage, done, total), stage "import" or "tessellate",
called in the caller's thread about ten times a second and when a stage ends (a FreeCAD
command may update a progress dialog and process events there); an exception it raises
stops the reports and is raised when the work has ended.

Returns a dict of numpy arrays and a summary:
  points           (N, 3) float64  vertex positions, shared where faces meet
  triangles        (T, 3) uint32   indices into points
  normals          (M, 3) float64  unit normals, per face: a crease keeps one on each side
  triangle_normals (T, 3) uint32   indices into normals, one per triangle corner
  face_ids         (T,)   int32    1-based face index: shape.Faces[face_id - 1]
  summary          dict: faces, triangles, vertices, seconds (tessellation),
                   total_seconds (the whole call), tolerance (absolute), mode,
                   faces_warned and faces_failed (lists of {face, reason}: meshed
                   with a word on the input, not meshed); the keys of the command
                   line's JSON summary

Raises ValueError for a bad tolerance, mode or thread count, NurbsLOD.ReadError (a
ValueError) for a file or shape that cannot be read.)");

    m.def("export", &exportMesh, py::arg("shape"), py::arg("path"),
          py::arg("tolerance") = py::none(), py::arg("relative") = py::none(),
          py::arg("mode") = "guaranteed", py::arg("threads") = 0, py::arg("progress") = py::none(),
          py::arg("compact") = false,
          R"(Tessellates the shape like tessellate() and writes the mesh to path.

The format follows the extension: .obj (one group per face, "g FaceN"), .ply, .stl, .off.
Returns the summary dict of tessellate(), with "output" (the path) added.)");

    m.def("analysis_mesh", &analysisMeshOf, py::arg("shape"), py::arg("tolerance") = py::none(),
          py::arg("relative") = py::none(), py::arg("mode") = "guaranteed", py::arg("threads") = 0,
          R"(Tessellates the shape like tessellate() for surface analysis displays.

Every vertex appears once per face that uses it, so each attribute is per vertex. Normals
and curvatures are the exact surface's at the vertex, not the mesh's.

Returns a dict of numpy arrays and a summary:
  points      (N, 3) float64  vertex positions (a point on an edge once per face)
  normals     (N, 3) float64  exact unit normals, outward (the face's orientation applied)
  parameters  (N, 2) float64  (u, v) of the vertex on its face's NURBS surface
  gaussian    (N,)   float64  Gaussian curvature (1/length^2)
  mean        (N,)   float64  mean curvature (1/length)
  minimum     (N,)   float64  principal curvatures, minimum <= maximum (1/length);
  maximum     (N,)   float64    positive where the face is convex, like a sphere
  triangles   (T, 3) uint32   indices into points
  face_ids    (T,)   int32    1-based face index: shape.Faces[face_id - 1]
  summary     dict: the keys of tessellate()'s summary (faces_failed lists the faces left
              out, with the reason), vertices counted as here, and singular_vertices (vertices
              at a singular point, a pole: normal and curvature taken from the limit inside))");

    m.def("to_mesh", &toMesh, py::arg("shape"), py::arg("tolerance") = py::none(),
          py::arg("relative") = py::none(), py::arg("mode") = "guaranteed", py::arg("threads") = 0,
          py::arg("progress") = py::none(), py::arg("compact") = false,
          R"(Tessellates the shape like tessellate() and returns a FreeCAD Mesh.Mesh.

Needs FreeCAD (freecad or freecadcmd).)");
}
