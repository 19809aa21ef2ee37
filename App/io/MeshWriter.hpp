#pragma once

#include <string>

#include "tessellate/Mesh.hpp"

namespace nurbslod {

// Writes the mesh to a file whose format is chosen by the extension (case-insensitive):
//   .obj  our own writer: full-precision positions, normals, one "g FaceN" group per B-rep face
//         (the form meshjudge and ObjMeshReader read back), positions shared between faces
//   .ply  binary PLY with vertex normals, through OpenMesh
//   .stl  binary STL (facet normals), through OpenMesh
//   .off  ASCII OFF with vertex normals, through OpenMesh
// Throws std::runtime_error naming the path and the reason (unknown extension, a mesh whose
// arrays do not fit together, a file that cannot be written).
void writeMesh(const Mesh& mesh, const std::string& path);

}  // namespace nurbslod
