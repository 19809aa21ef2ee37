#include "occ/ShapeReader.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <algorithm>
#include <filesystem>
#include <sstream>

namespace nurbslod::occ {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool hasFaces(const TopoDS_Shape& shape) {
    return !shape.IsNull() && TopExp_Explorer(shape, TopAbs_FACE).More();
}

TopoDS_Shape readStep(const std::string& path) {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw ModelReadError(path + ": not a readable STEP file");
    if (reader.TransferRoots() == 0) throw ModelReadError(path + ": STEP file holds no shape");
    return reader.OneShape();
}

TopoDS_Shape readIges(const std::string& path) {
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw ModelReadError(path + ": not a readable IGES file");
    if (reader.TransferRoots() == 0) throw ModelReadError(path + ": IGES file holds no shape");
    return reader.OneShape();
}

TopoDS_Shape readBrep(const std::string& path) {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder))
        throw ModelReadError(path + ": not a readable BREP file");
    return shape;
}

}  // namespace

TopoDS_Shape readShape(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw ModelReadError(path + ": no such file");
    const std::string ext = lowerExtension(path);
    TopoDS_Shape shape;
    try {
        if (ext == ".step" || ext == ".stp")
            shape = readStep(path);
        else if (ext == ".iges" || ext == ".igs")
            shape = readIges(path);
        else if (ext == ".brep" || ext == ".brp")
            shape = readBrep(path);
        else
            throw ModelReadError(path + ": unknown model format '" + ext +
                                 "' (expected .step, .stp, .iges, .igs, .brep or .brp)");
    } catch (const Standard_Failure& failure) {
        throw ModelReadError(path +
                             ": OpenCASCADE failed to read it: " + failure.GetMessageString());
    }
    if (!hasFaces(shape)) throw ModelReadError(path + ": the model has no faces");
    return shape;
}

TopoDS_Shape shapeFromBrepString(const std::string& brep) {
    TopoDS_Shape shape;
    try {
        std::istringstream stream(brep);
        BRep_Builder builder;
        BRepTools::Read(shape, stream, builder);
    } catch (const Standard_Failure& failure) {
        throw ModelReadError(std::string("BREP text could not be read: ") +
                             failure.GetMessageString());
    }
    if (!hasFaces(shape)) throw ModelReadError("the shape has no faces");
    return shape;
}

}  // namespace nurbslod::occ
