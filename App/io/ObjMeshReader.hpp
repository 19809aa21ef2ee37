#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "tessellate/Mesh.hpp"

namespace nurbslod {

// A mesh file that cannot be read: missing, unreadable or malformed. The message names the
// file and, for malformed text, the line.
class MeshReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads an OBJ mesh whose triangles are grouped by B-rep face: "g FaceN" (or "o FaceN") puts
// the following faces in B-rep face N (1-based, FreeCAD's shape.Faces order), as meshjudge
// reads it. Understands "v", "vn" and "f" with the a, a/b, a//c and a/b/c forms and negative
// (relative) indices; polygons are fanned into triangles. Normals are kept only when every
// corner of every face names one. A face outside a FaceN group is an error, as in meshjudge.
// Throws MeshReadError.
Mesh readObjMesh(const std::string& path);

// The same from text in memory; `name` is used in error messages.
Mesh parseObjMesh(std::string_view text, const std::string& name);

}  // namespace nurbslod
