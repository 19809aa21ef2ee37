#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "occ/ShapeReader.hpp"

namespace nurbslod::test {

// Real models that Debian installs with the project's dependencies: OpenCASCADE's samples
// (occt-misc, which libocct-foundation-dev depends on) and FreeCAD's IDF library of electronic
// packages (freecad).
inline const std::filesystem::path kOpenCascadeSamples = "/usr/share/opencascade/data/occ";
inline const std::filesystem::path kFreecadIdfLibrary = "/usr/share/freecad/Mod/Idf/Idflibs";

// The model at `path` (an OpenCASCADE .rle sample read as the BREP text it is), or none where it
// is not installed: the test then skips.
inline std::optional<TopoDS_Shape> sampleModel(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) return std::nullopt;
    if (path.extension() != ".rle") return occ::readShape(path.string());
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return occ::shapeFromBrepString(text.str());
}

}  // namespace nurbslod::test
