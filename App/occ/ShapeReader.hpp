#pragma once

#include <TopoDS_Shape.hxx>
#include <stdexcept>
#include <string>

namespace nurbslod::occ {

// A model file that cannot be read: missing, malformed, or without faces.
class ModelReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads a STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp) file, by extension, into
// one shape. Throws ModelReadError with a message naming the file and what went wrong.
TopoDS_Shape readShape(const std::string& path);

// The shape written by FreeCAD's shape.exportBrepToString().
TopoDS_Shape shapeFromBrepString(const std::string& brep);

}  // namespace nurbslod::occ
