// The Python module NurbsLODCoin: registers the Coin node SoNurbsLODShape and talks to the
// nodes that pivy created (FreeCAD's Python side builds the scene graph through pivy).
//
// A pivy node crosses as its SWIG pointer: int(node.this) is the address of the C++ node.
// Its Coin type is checked before the pointer is used, so a wrong object is a TypeError, not
// a crash. Every C++ failure becomes a Python exception; none escapes into FreeCAD.

#include <Inventor/SoDB.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Standard_Failure.hxx>
#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include "SoNurbsLODEdges.hpp"
#include "SoNurbsLODShape.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"

namespace py = pybind11;

namespace nurbslod::gui::python {
namespace {

using Clock = std::chrono::steady_clock;

SoNurbsLODShape* nodeOf(const py::object& node) {
    if (!py::hasattr(node, "this") || !py::hasattr(node, "getTypeId"))
        throw py::type_error("NurbsLODCoin: expected a pivy SoNurbsLODShape node");
    const std::string typeName =
        node.attr("getTypeId")().attr("getName")().attr("getString")().cast<std::string>();
    if (typeName != "SoNurbsLODShape")
        throw py::type_error("NurbsLODCoin: expected an SoNurbsLODShape node, got " + typeName);
    const auto address = py::int_(node.attr("this")).cast<std::uintptr_t>();
    auto* shape = reinterpret_cast<SoNurbsLODShape*>(address);
    if (!shape || !shape->isOfType(SoNurbsLODShape::getClassTypeId()))
        throw py::type_error("NurbsLODCoin: the node is not an SoNurbsLODShape");
    return shape;
}

std::shared_ptr<const Model> importBrep(const std::string& brep) {
    py::gil_scoped_release release;
    return std::make_shared<const Model>(occ::importModel(occ::shapeFromBrepString(brep)));
}

py::list failureList(const FaceLodCache& cache) {
    py::list list;
    for (const auto& failure : cache.failures()) {
        py::dict entry;
        entry["face"] = failure.face;
        entry["reason"] = failure.reason;
        list.append(entry);
    }
    return list;
}

// Gives the node the model of a FreeCAD shape (its BREP text) and makes every face's
// coarsest level. Returns {faces, faces_failed: [{face, reason}], seconds}.
py::dict setShape(const py::object& node, const std::string& brep) {
    SoNurbsLODShape* shape = nodeOf(node);
    const auto start = Clock::now();
    std::shared_ptr<const Model> model = importBrep(brep);
    {
        py::gil_scoped_release release;
        shape->setModel(std::move(model));
    }
    py::dict out;
    out["faces"] = shape->cache()->faceCount();
    out["faces_failed"] = failureList(*shape->cache());
    out["seconds"] = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
}

// A model imported and given its coarsest levels away from the GUI thread, waiting to be
// installed into a node.
struct PreparedModel {
    std::unique_ptr<FaceLodCache> cache;
    double seconds = 0;
};

// The slow part of set_shape (import, every face's coarsest level), without the GIL and
// without touching Coin, so a Python thread can run it while FreeCAD keeps drawing.
std::shared_ptr<PreparedModel> prepare(const std::string& brep) {
    auto prepared = std::make_shared<PreparedModel>();
    py::gil_scoped_release release;
    const auto start = Clock::now();
    auto model = std::make_shared<const Model>(occ::importModel(occ::shapeFromBrepString(brep)));
    if (model->faces.empty()) throw std::invalid_argument("the shape has no faces to display");
    prepared->cache = std::make_unique<FaceLodCache>(std::move(model));
    prepared->seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return prepared;
}

// Gives the node a prepared model (in the GUI thread: it touches the scene graph).
py::dict install(const py::object& node, PreparedModel& prepared) {
    SoNurbsLODShape* shape = nodeOf(node);
    if (!prepared.cache) throw py::value_error("NurbsLODCoin: this model was installed already");
    shape->setCache(std::move(prepared.cache));
    py::dict out;
    out["faces"] = shape->cache()->faceCount();
    out["faces_failed"] = failureList(*shape->cache());
    out["seconds"] = prepared.seconds;
    return out;
}

py::dict stats(const py::object& node) {
    SoNurbsLODShape* shape = nodeOf(node);
    const FrameStats s = shape->stats();
    py::dict out;
    out["triangles"] = s.triangles;
    out["max_screen_error_px"] = s.maxScreenErrorPx;
    out["max_normal_error_deg"] = s.maxNormalErrorDeg;
    out["faces_shading_limited"] = s.facesShadingLimited;
    out["faces_normal_error_over"] = s.facesNormalErrorOver;
    out["last_frame_tessellation_ms"] = s.lastFrameTessellationMs;
    out["last_frame_tessellation_cpu_ms"] = s.lastFrameTessellationCpuMs;
    out["last_frame_selection_ms"] = s.selectionMs;
    out["faces_visible"] = s.facesVisible;
    out["faces_culled"] = s.facesCulled;
    out["faces_failed"] = s.facesFailed;
    out["faces_waiting"] = s.facesWaiting;
    out["pending_jobs"] = s.pendingJobs;
    out["background_tessellation_ms"] = s.workerMs;
    out["frames"] = s.frames;
    out["face_triangles"] = s.faceTriangles;
    out["face_normal_error_deg"] = s.faceNormalErrorDeg;
    out["pixel_error"] = shape->pixelError.getValue();
    out["frame_budget_ms"] = shape->frameBudget.getValue();
    out["normal_error_deg"] = shape->normalError.getValue();
    out["last_error"] = shape->lastError();
    if (shape->hasModel()) out["failures"] = failureList(*shape->cache());
    return out;
}

// An edit of one face: `brep` holds the new face alone. Only that face is tessellated again,
// at `level` (0, the coarsest, by default: paper out-of-core-lod 6.4 applies an edit at once
// with the coarsest level), in this thread; its other levels are dropped, and the next frames
// ask the workers for the level the view needs. Returns {import_ms, tessellate_ms, total_ms,
// level, triangles}.
py::dict replaceFace(const py::object& node, int faceIndex, const std::string& brep, int level) {
    SoNurbsLODShape* shape = nodeOf(node);
    if (!shape->hasModel()) throw py::value_error("NurbsLODCoin: the node has no model yet");
    if (faceIndex < 1 || faceIndex > shape->cache()->faceCount())
        throw py::value_error("NurbsLODCoin: no face " + std::to_string(faceIndex) + " (1 to " +
                              std::to_string(shape->cache()->faceCount()) + ")");
    const auto start = Clock::now();
    double importMs = 0, tessellateMs = 0;
    FaceLodCache& cache = *shape->cache();
    level = std::clamp(level, 0, cache.finestLevel());
    {
        py::gil_scoped_release release;
        const Model replacement = occ::importModel(occ::shapeFromBrepString(brep));
        importMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (replacement.faces.size() != 1)
            throw std::invalid_argument("the replacement shape must have exactly one face, not " +
                                        std::to_string(replacement.faces.size()));
        if (!replacement.faces.front().error.empty())
            throw std::invalid_argument("face " + std::to_string(faceIndex) + ": " +
                                        replacement.faces.front().error);
        tessellateMs = cache.replaceFace(faceIndex - 1, replacement, level);
    }
    shape->touch();
    py::dict out;
    out["import_ms"] = importMs;
    out["tessellate_ms"] = tessellateMs;
    out["total_ms"] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    out["level"] = level;
    out["triangles"] = cache.bestCached(faceIndex - 1, level, nullptr)->triangleCount();
    return out;
}

// An edit that keeps the face's loops: pole (i, j) (1-based, as Part.BSplineSurface counts)
// moves to `position`; no BREP crosses. Only for surfaces the importer took over pole for
// pole (not periodic). Returns {tessellate_ms, total_ms, level, triangles}.
py::dict movePole(const py::object& node, int faceIndex, int i, int j,
                  const std::array<double, 3>& position, int level) {
    SoNurbsLODShape* shape = nodeOf(node);
    if (!shape->hasModel()) throw py::value_error("NurbsLODCoin: the node has no model yet");
    const auto start = Clock::now();
    FaceLodCache& cache = *shape->cache();
    level = std::clamp(level, 0, cache.finestLevel());
    double tessellateMs = 0;
    try {
        py::gil_scoped_release release;
        tessellateMs = cache.movePole(faceIndex - 1, i - 1, j - 1,
                                      Point3(position[0], position[1], position[2]), level);
    } catch (const std::out_of_range& error) {
        throw py::value_error(std::string("NurbsLODCoin: ") + error.what());
    } catch (const std::invalid_argument& error) {
        throw py::value_error(std::string("NurbsLODCoin: ") + error.what());
    }
    shape->touch();
    py::dict out;
    out["import_ms"] = 0.0;
    out["tessellate_ms"] = tessellateMs;
    out["total_ms"] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    out["level"] = level;
    out["triangles"] = cache.bestCached(faceIndex - 1, level, nullptr)->triangleCount();
    return out;
}

int shownLevel(const py::object& node, int faceIndex) {
    SoNurbsLODShape* shape = nodeOf(node);
    if (!shape->hasModel()) return -1;
    return shape->shownLevel(faceIndex - 1);
}

// The box of the level face `face` (1-based) showed last (its coarsest before any frame):
// ((xmin, ymin, zmin), (xmax, ymax, zmax)), or None for a face that has no level.
py::object faceBounds(const py::object& node, int faceIndex) {
    SoNurbsLODShape* shape = nodeOf(node);
    if (!shape->hasModel() || faceIndex < 1 || faceIndex > shape->cache()->faceCount())
        return py::none();
    const FaceLod* lod = shape->cache()->bestCached(
        faceIndex - 1, std::max(shape->shownLevel(faceIndex - 1), 0), nullptr);
    if (!lod) return py::none();
    return py::make_tuple(py::make_tuple(lod->boxMin[0], lod->boxMin[1], lod->boxMin[2]),
                          py::make_tuple(lod->boxMax[0], lod->boxMax[1], lod->boxMax[2]));
}

void translateFailures() {
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const Standard_Failure& failure) {
            const std::string message =
                std::string("NurbsLODCoin: OpenCASCADE failed: ") + failure.GetMessageString();
            PyErr_SetString(PyExc_RuntimeError, message.c_str());
        } catch (const occ::ModelReadError& failure) {
            PyErr_SetString(PyExc_ValueError,
                            (std::string("NurbsLODCoin: ") + failure.what()).c_str());
        }
    });
}

}  // namespace
}  // namespace nurbslod::gui::python

PYBIND11_MODULE(NurbsLODCoin, m) {
    using namespace nurbslod::gui::python;
    m.doc() =
        "Coin nodes of NurbsLOD. Importing registers SoNurbsLODShape; create one with\n"
        "coin.SoType.fromName(coin.SbName('SoNurbsLODShape')).createInstance().";
    // Outside FreeCAD's GUI nothing has initialised Coin, and Coin crashes uninitialised.
    if (!SoDB::isInitialized()) SoDB::init();
    SoNurbsLODShape::initClass();
    SoNurbsLODEdges::initClass();
    // The report view, through FreeCAD's Python console (FreeCAD ships no C++ headers).
    SoNurbsLODShape::reportError = [](const std::string& message) {
        if (!Py_IsInitialized()) return;  // FreeCAD is shutting down
        py::gil_scoped_acquire gil;
        try {
            py::module_::import("FreeCAD").attr("Console").attr("PrintWarning")(
                "NurbsLOD: " + message + "\n");
        } catch (py::error_already_set&) {  // outside FreeCAD: nowhere to report
        }
    };
    translateFailures();

    m.def("set_shape", &setShape, py::arg("node"), py::arg("brep"),
          "Gives the node the model of shape.exportBrepToString(); returns {faces, "
          "faces_failed: [{face, reason}], seconds}.");
    py::class_<PreparedModel, std::shared_ptr<PreparedModel>>(
        m, "PreparedModel", "A model imported with its coarsest levels, for install().");
    m.def("prepare", &prepare, py::arg("brep"),
          "Imports shape.exportBrepToString() and makes every face's coarsest level, without "
          "the GIL and without touching Coin (run it in a thread); returns a PreparedModel.");
    m.def("install", &install, py::arg("node"), py::arg("prepared"),
          "Gives the node a PreparedModel (in the GUI thread); returns {faces, faces_failed: "
          "[{face, reason}], seconds}.");
    m.def("stats", &stats, py::arg("node"),
          "What the node's last frame drew: triangles, max_screen_error_px, "
          "max_normal_error_deg (measured, interpolated normals), faces_shading_limited, "
          "faces_normal_error_over, last_frame_tessellation_ms, "
          "faces_visible, faces_culled, faces_failed, "
          "faces_waiting, pending_jobs, background_tessellation_ms, frames, face_triangles "
          "(per face, 0: not drawn), face_normal_error_deg (per face), failures.");
    m.def("replace_face", &replaceFace, py::arg("node"), py::arg("face"), py::arg("brep"),
          py::arg("level") = 0,
          "Replaces face `face` (1-based) by the one face of `brep` and tessellates only it, at "
          "`level` (0: the coarsest); finer levels follow from the workers. Returns {import_ms, "
          "tessellate_ms, total_ms, level, triangles}.");
    m.def("move_pole", &movePole, py::arg("node"), py::arg("face"), py::arg("i"), py::arg("j"),
          py::arg("position"), py::arg("level") = 0,
          "Moves pole (i, j) (1-based) of face `face` (1-based) to position (x, y, z) and "
          "tessellates only that face at `level`; returns {import_ms, tessellate_ms, total_ms, "
          "level, triangles}.");
    m.def("face_bounds", &faceBounds, py::arg("node"), py::arg("face"),
          "The box of the level face `face` (1-based) showed last, or None.");
    m.def("shown_level", &shownLevel, py::arg("node"), py::arg("face"),
          "The level face `face` (1-based) showed in the last frame, -1 when not drawn.");
}
