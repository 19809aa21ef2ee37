// brepmesh_timer: time OpenCASCADE's BRepMesh_IncrementalMesh in-process, as the baseline the
// model benchmark (model_benchmark.py) compares NurbsLOD with, and write its triangulation as
// an OBJ with 'g FaceN' groups (TopExp::MapShapes face order, 1-based) for `nurbslod verify`.
//
// Usage: brepmesh_timer MODEL DEFLECTION OUT.obj [THREADS] [ANGULAR]
//   THREADS: 1 = sequential (default), anything else = BRepMesh's parallel mode (all cores;
//   BRepMesh cannot be limited to N threads). ANGULAR: radians, default 0.5.
// Last stdout line: {"faces":..,"triangles":..,"vertices":..,"seconds":..,"deflection":..}
// where seconds covers BRepMesh_IncrementalMesh only (not reading, not writing).
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "occ/ShapeReader.hpp"

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s MODEL DEFLECTION OUT.obj [THREADS] [ANGULAR]\n", argv[0]);
        return 2;
    }
    const std::string model = argv[1], out = argv[3];
    const double deflection = std::atof(argv[2]);
    const int threads = argc > 4 ? std::atoi(argv[4]) : 1;
    const double angular = argc > 5 ? std::atof(argv[5]) : 0.5;
    try {
        TopoDS_Shape shape = nurbslod::occ::readShape(model);
        BRepTools::Clean(shape);  // a .brep may carry a triangulation BRepMesh would reuse
        const auto start = std::chrono::steady_clock::now();
        BRepMesh_IncrementalMesh mesher(shape, deflection, /*relative*/ false, angular,
                                        /*parallel*/ threads != 1);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(shape, TopAbs_FACE, faces);
        std::FILE* file = std::fopen(out.c_str(), "w");
        if (!file) {
            std::fprintf(stderr, "brepmesh_timer: cannot write %s\n", out.c_str());
            return 2;
        }
        std::size_t base = 0, triangles = 0;
        for (int i = 1; i <= faces.Extent(); ++i) {
            const TopoDS_Face& face = TopoDS::Face(faces(i));
            TopLoc_Location location;
            const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
            if (mesh.IsNull() || mesh->NbTriangles() == 0) continue;
            const gp_Trsf transform = location.Transformation();
            for (int n = 1; n <= mesh->NbNodes(); ++n) {
                const gp_Pnt p = mesh->Node(n).Transformed(transform);
                std::fprintf(file, "v %.17g %.17g %.17g\n", p.X(), p.Y(), p.Z());
            }
            std::fprintf(file, "g Face%d\n", i);
            const bool reversed = face.Orientation() == TopAbs_REVERSED;
            for (int t = 1; t <= mesh->NbTriangles(); ++t) {
                int a, b, c;
                mesh->Triangle(t).Get(a, b, c);
                if (reversed) std::swap(b, c);
                std::fprintf(file, "f %zu %zu %zu\n", base + a, base + b, base + c);
            }
            base += static_cast<std::size_t>(mesh->NbNodes());
            triangles += static_cast<std::size_t>(mesh->NbTriangles());
        }
        std::fclose(file);
        std::printf(
            "{\"faces\":%d,\"triangles\":%zu,\"vertices\":%zu,\"seconds\":%.6g,"
            "\"deflection\":%.6g,\"parallel\":%s}\n",
            faces.Extent(), triangles, base, seconds, deflection, threads != 1 ? "true" : "false");
        return 0;
    } catch (const Standard_Failure& failure) {
        std::fprintf(stderr, "brepmesh_timer: OpenCASCADE failed: %s\n",
                     failure.GetMessageString());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "brepmesh_timer: %s\n", error.what());
    }
    return 3;
}
