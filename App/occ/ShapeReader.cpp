#include "occ/ShapeReader.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "occ/SignalsAsFailures.hpp"

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

// What OpenCASCADE's translator said of the first entity it failed on, as the end of a message
// (" that OpenCASCADE could translate: ..."); empty where it reported none. A fault in the
// translator (SignalsAsFailures) is reported so, per entity.
std::string transferFailure(const XSControl_Reader& reader) {
    const Handle(XSControl_WorkSession)& session = reader.WS();
    if (session.IsNull() || session->TransferReader().IsNull() ||
        session->TransferReader()->TransientProcess().IsNull())
        return {};
    const Interface_CheckIterator checks =
        session->TransferReader()->TransientProcess()->CheckList(false);
    for (checks.Start(); checks.More(); checks.Next()) {
        const Handle(Interface_Check)& check = checks.Value();
        if (!check.IsNull() && check->HasFailed())
            return std::string(" that OpenCASCADE could translate: ") + check->CFail(1);
    }
    return {};
}

TopoDS_Shape readStep(const std::string& path) {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw ModelReadError(path + ": not a readable STEP file");
    if (reader.TransferRoots() == 0)
        throw ModelReadError(path + ": STEP file holds no shape" + transferFailure(reader));
    return reader.OneShape();
}

TopoDS_Shape readIges(const std::string& path) {
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw ModelReadError(path + ": not a readable IGES file");
    if (reader.TransferRoots() == 0)
        throw ModelReadError(path + ": IGES file holds no shape" + transferFailure(reader));
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
    // a malformed file can make OpenCASCADE's translators fault (SignalsAsFailures)
    const SignalsAsFailures faults;
    try {
        OCC_CATCH_SIGNALS
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
    const SignalsAsFailures faults;
    try {
        OCC_CATCH_SIGNALS
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
