// nurbslod: the command-line front door.
//   nurbslod tessellate MODEL -o OUT.{obj,ply,stl,off} [--tolerance T | --relative R] ...
//   nurbslod verify MODEL MESH.obj (--tolerance T | --relative R)
// Exit codes: 0 success (verify: PASS), 1 verify FAIL, 2 bad input (arguments, unreadable or
// malformed files), 3 an internal error.

#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/MeshWriter.hpp"
#include "io/ObjMeshReader.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeDiagonal.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"
#include "tessellate/ToleranceRequest.hpp"

namespace {

using namespace nurbslod;

constexpr int exitSuccess = 0;
constexpr int exitVerifyFailed = 1;
constexpr int exitBadInput = 2;
constexpr int exitInternalError = 3;

// Bad arguments or files: reported in one line, exit code 2.
class BadInput : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// ---- JSON, written by hand: the objects are small and flat -------------------------------

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\b':
                out += "\\b";
                break;
            case '\f':
                out += "\\f";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (c < 0x20) {
                    char escaped[8];
                    std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                    out += escaped;
                } else {
                    out += static_cast<char>(c);  // UTF-8 passes through unchanged
                }
        }
    }
    return out + "\"";
}

// JSON has no NaN or infinity.
std::string jsonNumber(double value) {
    if (!std::isfinite(value)) return "null";
    char digits[32];
    const auto [end, error] = std::to_chars(digits, digits + sizeof digits, value);
    return error == std::errc() ? std::string(digits, end) : "null";
}

// [{"face":N,"reason":"..."}, ...]
std::string faceList(const std::vector<FaceFailure>& faces) {
    std::string out = "[";
    for (std::size_t i = 0; i < faces.size(); ++i)
        out += std::string(i ? "," : "") + "{\"face\":" + std::to_string(faces[i].face) +
               ",\"reason\":" + jsonString(faces[i].reason) + "}";
    return out + "]";
}

std::string jsonIntegers(const std::vector<int>& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i)
        out += (i ? "," : "") + std::to_string(values[i]);
    return out + "]";
}

// ---- tolerance arguments -------------------------------------------------------------------

// Parsed by hand rather than by CLI11 so that "nan", "inf", "1e999" and "0.1mm" all get a
// message that says what is wrong with them.
double positiveNumber(const std::string& text, const std::string& option) {
    double value = 0;
    const char* begin = text.data() + (text.starts_with('+') ? 1 : 0);
    const char* end = text.data() + text.size();
    const auto [last, error] = std::from_chars(begin, end, value);
    if (text.empty() || error == std::errc::invalid_argument || last != end)
        throw BadInput(option + " must be a number, not '" + text + "'");
    if (error == std::errc::result_out_of_range || !std::isfinite(value))
        throw BadInput(option + " must be a finite number, not '" + text + "'");
    if (!(value > 0)) throw BadInput(option + " must be greater than 0, not '" + text + "'");
    return value;
}

struct ToleranceArguments {
    std::string absolute, relative;  // as typed; empty when not given
};

double absoluteTolerance(const ToleranceArguments& arguments, double diagonal,
                         double defaultRelative) {
    ToleranceRequest request;
    if (!arguments.absolute.empty())
        request.absolute = positiveNumber(arguments.absolute, "--tolerance");
    if (!arguments.relative.empty())
        request.relative = positiveNumber(arguments.relative, "--relative");
    try {
        return resolveTolerance(request, diagonal, defaultRelative,
                                {.absolute = "--tolerance", .relative = "--relative"});
    } catch (const std::invalid_argument& error) {
        throw BadInput(error.what());
    }
}

void addToleranceOptions(CLI::App* command, ToleranceArguments& arguments,
                         const std::string& relativeNote) {
    CLI::Option* absolute = command->add_option("--tolerance,-t", arguments.absolute,
                                                "absolute tolerance in model units (> 0)");
    CLI::Option* relative = command->add_option(
        "--relative,-r", arguments.relative,
        "tolerance as a fraction of the model's bounding-box diagonal" + relativeNote);
    absolute->excludes(relative);
}

// ---- tessellate ----------------------------------------------------------------------------

// Prints "<what> 120/415 faces" (imported, tessellated) on stderr at most every half second,
// and the final count where it printed any. Called from worker threads: a thread that finds
// another one printing simply goes on.
class ProgressPrinter {
public:
    explicit ProgressPrinter(const char* what) : what_(what) {}
    void operator()(std::size_t done, std::size_t total) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock()) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < interval) return;
        last_ = now;
        printed_ = true;
        std::fprintf(stderr, "%s %zu/%zu faces\n", what_, done, total);
        std::fflush(stderr);
    }
    void finish(std::size_t total) const {
        if (!printed_) return;
        std::fprintf(stderr, "%s %zu/%zu faces\n", what_, total, total);
        std::fflush(stderr);
    }

private:
    static constexpr std::chrono::milliseconds interval{500};
    const char* what_;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
    bool printed_ = false;
};

struct TessellateArguments {
    std::string model, output, mode = "guaranteed";
    ToleranceArguments tolerance;
    int threads = 0;
    bool compact = false;
};

TopoDS_Shape readModel(const std::string& path) {
    try {
        return occ::readShape(path);
    } catch (const occ::ModelReadError& error) {
        throw BadInput(error.what());
    }
}

int runTessellate(const TessellateArguments& arguments) {
    const auto start = std::chrono::steady_clock::now();
    if (arguments.threads < 0) throw BadInput("--threads must be 0 (all cores) or more");
    // refuse a bad tolerance or output name before the slow reading
    if (!arguments.tolerance.absolute.empty())
        positiveNumber(arguments.tolerance.absolute, "--tolerance");
    if (!arguments.tolerance.relative.empty())
        positiveNumber(arguments.tolerance.relative, "--relative");
    std::string extension = std::filesystem::path(arguments.output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".off")
        throw BadInput("-o " + arguments.output +
                       ": the output must end in .obj, .ply, .stl or .off");

    const TopoDS_Shape shape = readModel(arguments.model);
    const auto read = std::chrono::steady_clock::now();
    ProgressPrinter importing("imported");
    const Model model = occ::importModel(
        shape, arguments.threads,
        [&importing](std::size_t done, std::size_t total) { importing(done, total); });
    importing.finish(model.faces.size());
    const auto imported = std::chrono::steady_clock::now();

    TessellationOptions options;
    options.tolerance =
        absoluteTolerance(arguments.tolerance, model.boundingBoxDiagonal, defaultRelativeTolerance);
    options.mode = arguments.mode == "approximate" ? ErrorMode::Approximate : ErrorMode::Guaranteed;
    options.threads = arguments.threads;
    options.compact = arguments.compact;
    auto progress = std::make_shared<ProgressPrinter>("tessellated");
    options.progress = [progress](std::size_t done, std::size_t total) {
        (*progress)(done, total);
    };

    TessellationResult result;
    try {
        result = tessellateModel(model, options);
    } catch (const std::invalid_argument& error) {
        throw BadInput(arguments.model + ": " + error.what());  // a tolerance the model cannot hold
    }
    progress->finish(static_cast<std::size_t>(result.faces));

    try {
        writeMesh(result.mesh, arguments.output);
    } catch (const std::runtime_error& error) {
        throw BadInput(error.what());
    }

    const double totalSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string json =
        "{\"faces\":" + std::to_string(model.faces.size()) +
        ",\"triangles\":" + std::to_string(result.mesh.triangles.size()) +
        ",\"vertices\":" + std::to_string(result.mesh.positions.size()) +
        ",\"seconds\":" + jsonNumber(result.seconds) +
        ",\"total_seconds\":" + jsonNumber(totalSeconds) +
        ",\"read_seconds\":" + jsonNumber(std::chrono::duration<double>(read - start).count()) +
        ",\"import_seconds\":" +
        jsonNumber(std::chrono::duration<double>(imported - read).count()) +
        ",\"tolerance\":" + jsonNumber(options.tolerance) +
        ",\"mode\":" + jsonString(arguments.mode) + ",\"output\":" + jsonString(arguments.output) +
        ",\"faces_warned\":" + faceList(result.warnings) +
        ",\"faces_failed\":" + faceList(result.failures) + "}";
    std::cout << json << std::endl;
    return exitSuccess;
}

// ---- verify --------------------------------------------------------------------------------

struct VerifyArguments {
    std::string model, mesh, jsonPath;
    ToleranceArguments tolerance;
    int threads = 0;
};

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::string faceJson(const occ::FaceDeviation& face) {
    return "{\"face\":" + std::to_string(face.face) +
           ",\"triangles\":" + std::to_string(face.triangles) + ",\"dev\":" + jsonNumber(face.dev) +
           ",\"cover\":" + jsonNumber(face.cover) +
           ",\"edge_tolerance\":" + jsonNumber(face.edgeTolerance) +
           ",\"measured\":" + (face.measured ? "true" : "false") +
           (face.problem.empty() ? "" : ",\"problem\":" + jsonString(face.problem)) + "}";
}

std::string reportJson(const occ::VerificationReport& report, const std::string& mesh,
                       bool allFaces) {
    std::string json = "{\"faces\":" + std::to_string(report.shapeFaces) +
                       ",\"triangles\":" + std::to_string(report.triangles) +
                       ",\"vertices\":" + std::to_string(report.vertices) +
                       ",\"max_dev\":" + jsonNumber(report.maxDev) +
                       ",\"max_cover\":" + jsonNumber(report.maxCover) +
                       ",\"tolerance\":" + jsonNumber(report.tolerance) +
                       ",\"faces_over_tol\":" + jsonIntegers(report.facesOverTolerance) +
                       ",\"faces_missing\":" + jsonIntegers(report.facesMissing) +
                       ",\"faces_unmeasured\":" + jsonIntegers(report.facesUnmeasured) +
                       ",\"open_edges\":" + std::to_string(report.openEdges) +
                       ",\"nonmanifold_edges\":" + std::to_string(report.nonManifoldEdges) +
                       ",\"degenerate_triangles\":" + std::to_string(report.degenerateTriangles) +
                       ",\"seconds\":" + jsonNumber(report.seconds) +
                       ",\"mesh\":" + jsonString(mesh) +
                       ",\"pass\":" + (report.pass ? "true" : "false");
    // stdout carries the faces that need attention; --json FILE carries them all
    json += allFaces ? ",\"per_face\":[" : ",\"faces_failed\":[";
    bool first = true;
    for (const occ::FaceDeviation& face : report.faces) {
        const bool over = face.dev > report.tolerance || face.cover > report.tolerance;
        if (!allFaces && face.measured && !over) continue;
        json += (first ? "" : ",") + faceJson(face);
        first = false;
    }
    return json + "]}";
}

int runVerify(const VerifyArguments& arguments) {
    if (arguments.threads < 0) throw BadInput("--threads must be 0 (all cores) or more");
    if (arguments.tolerance.absolute.empty() && arguments.tolerance.relative.empty())
        throw BadInput("give the tolerance: --tolerance T or --relative R");
    if (!arguments.tolerance.absolute.empty())
        positiveNumber(arguments.tolerance.absolute, "--tolerance");
    if (!arguments.tolerance.relative.empty())
        positiveNumber(arguments.tolerance.relative, "--relative");
    std::string extension = std::filesystem::path(arguments.mesh).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj")
        throw BadInput(arguments.mesh +
                       ": verify reads OBJ meshes whose 'g FaceN' groups name the B-rep faces");
    std::optional<tbb::global_control> threadLimit;
    if (arguments.threads > 0)
        threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(arguments.threads));

    const TopoDS_Shape shape = readModel(arguments.model);
    Mesh mesh;
    try {
        mesh = readObjMesh(arguments.mesh);
    } catch (const MeshReadError& error) {
        throw BadInput(error.what());
    }
    const double tolerance =
        absoluteTolerance(arguments.tolerance, occ::boundingBoxDiagonal(shape), 0);

    occ::VerificationReport report;
    try {
        report = occ::verifyMesh(shape, mesh, tolerance);
    } catch (const std::invalid_argument& error) {
        throw BadInput(arguments.mesh + ": " + error.what());
    }

    bool headerPrinted = false;
    for (const occ::FaceDeviation& face : report.faces) {
        const bool over = face.dev > tolerance || face.cover > tolerance;
        if (face.measured && !over) continue;
        if (!headerPrinted) {
            std::printf("%8s %10s %12s %12s %12s  %s\n", "face", "triangles", "dev", "cover",
                        "edge_tol", "verdict");
            headerPrinted = true;
        }
        std::printf("%8d %10zu %12.4g %12.4g %12.4g  %s\n", face.face, face.triangles, face.dev,
                    face.cover, face.edgeTolerance,
                    face.measured ? "OVER" : ("not measured: " + face.problem).c_str());
    }
    for (int face : report.facesMissing) std::printf("%8d %10d  missing\n", face, 0);
    std::printf(
        "faces %d  triangles %zu  vertices %zu  max_dev %s  max_cover %s  tol %s  over_tol %zu  "
        "missing %zu  unmeasured %zu  open_edges %zu  nonmanifold %zu  degenerate %zu  -> %s\n",
        report.shapeFaces, report.triangles, report.vertices, formatNumber(report.maxDev).c_str(),
        formatNumber(report.maxCover).c_str(), formatNumber(tolerance).c_str(),
        report.facesOverTolerance.size(), report.facesMissing.size(), report.facesUnmeasured.size(),
        report.openEdges, report.nonManifoldEdges, report.degenerateTriangles,
        report.pass ? "PASS" : "FAIL");
    if (!arguments.jsonPath.empty()) {
        std::ofstream file(arguments.jsonPath);
        file << reportJson(report, arguments.mesh, true) << '\n';
        if (!file) throw BadInput("cannot write " + arguments.jsonPath);
    }
    std::cout << reportJson(report, arguments.mesh, false) << std::endl;
    return report.pass ? exitSuccess : exitVerifyFailed;
}

}  // namespace

// OpenCASCADE's readers report on its default messenger, which prints to stdout
// (`*** ERR StepReaderData : Unresolved Reference` for a broken STEP file, sent as information;
// the IGES reader's count of entities): scripts read the summary from stdout, so these go to
// stderr, with the progress, and without the terminal colours OpenCASCADE adds.
void openCascadeMessagesToStderr() {
    const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
    messenger->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    Handle(Message_PrinterOStream) printer =
        new Message_PrinterOStream("cerr", Standard_False, Message_Info);
    printer->SetToColorize(Standard_False);
    messenger->AddPrinter(printer);
}

int main(int argc, char** argv) {
    openCascadeMessagesToStderr();
    CLI::App app{"NurbsLOD: tessellate trimmed NURBS B-rep models with a guaranteed error"};
    app.footer(
        "Exit codes: 0 success (verify: PASS), 1 verify FAIL, 2 bad input, 3 internal error.");
    app.require_subcommand(1);

    TessellateArguments tessellate;
    CLI::App* tessellateCommand = app.add_subcommand(
        "tessellate", "tessellate a STEP, IGES or BREP model within a tolerance");
    tessellateCommand->add_option("MODEL", tessellate.model, "the model file")->required();
    tessellateCommand
        ->add_option("-o,--output", tessellate.output, "the mesh: .obj, .ply, .stl or .off")
        ->required();
    addToleranceOptions(tessellateCommand, tessellate.tolerance, " (default 1e-3)");
    tessellateCommand
        ->add_option("--mode", tessellate.mode,
                     "guaranteed: never more than the tolerance; approximate: fewer triangles")
        ->check(CLI::IsMember({"guaranteed", "approximate"}));
    tessellateCommand->add_option("--threads", tessellate.threads, "0: all cores");
    tessellateCommand->add_flag(
        "--compact", tessellate.compact,
        "guaranteed mode: fewer triangles within the same tolerance, for more time (inner points "
        "removed where every new triangle is bounded against the surface)");

    VerifyArguments verify;
    CLI::App* verifyCommand = app.add_subcommand(
        "verify", "measure a mesh's real deviation from the exact model, face by face");
    verifyCommand->add_option("MODEL", verify.model, "the model file")->required();
    verifyCommand->add_option("MESH", verify.mesh, "an OBJ mesh with 'g FaceN' groups")->required();
    addToleranceOptions(verifyCommand, verify.tolerance, "");
    verifyCommand->add_option("--threads", verify.threads, "0: all cores");
    verifyCommand->add_option("--json", verify.jsonPath, "write the full per-face report here");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? exitSuccess : exitBadInput;  // --help is not an error
    }

    try {
        if (tessellateCommand->parsed()) return runTessellate(tessellate);
        return runVerify(verify);
    } catch (const BadInput& error) {
        std::fprintf(stderr, "nurbslod: %s\n", error.what());
        return exitBadInput;
    } catch (const Standard_Failure& failure) {
        std::fprintf(stderr, "nurbslod: OpenCASCADE failed: %s\n", failure.GetMessageString());
        return exitInternalError;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "nurbslod: %s\n", error.what());
        return exitInternalError;
    }
}
