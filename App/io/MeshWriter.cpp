#include "io/MeshWriter.hpp"

// MeshIO.hh must come before the mesh type so that OpenMesh's readers and writers register.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <system_error>

namespace nurbslod {

namespace {

// Double precision so that the ASCII formats keep every digit of our positions.
struct DoublePrecisionTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    VertexAttributes(OpenMesh::Attributes::Normal);
    FaceAttributes(OpenMesh::Attributes::Normal);
};
using OpenMeshTriangleMesh = OpenMesh::TriMesh_ArrayKernelT<DoublePrecisionTraits>;

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// OpenMesh reports every refused triangle on its error stream and chats about the file it
// writes on its log stream: noise to the user of a command-line tool whose stdout must end in
// JSON. Both are quiet while one of these lives.
class QuietOpenMesh {
public:
    QuietOpenMesh() : errors_(omerr().is_enabled()), log_(omlog().is_enabled()) {
        omerr().disable();
        omlog().disable();
    }
    ~QuietOpenMesh() {
        if (errors_) omerr().enable();
        if (log_) omlog().enable();
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
    bool errors_, log_;
};

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw std::runtime_error("cannot write mesh " + path + ": " + reason);
}

// A mesh whose index arrays point past their targets would make every writer read garbage.
void checkConsistent(const Mesh& mesh, const std::string& path) {
    const std::size_t positionCount = mesh.positions.size();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t index : mesh.triangles[t])
            if (index >= positionCount)
                fail(path, "triangle " + std::to_string(t) + " uses position " +
                               std::to_string(index) + " of " + std::to_string(positionCount));
    if (!mesh.triangleFaces.empty()) {
        if (mesh.triangleFaces.size() != mesh.triangles.size())
            fail(path, "the mesh has " + std::to_string(mesh.triangles.size()) + " triangles but " +
                           std::to_string(mesh.triangleFaces.size()) + " face ids");
        for (std::size_t t = 0; t < mesh.triangleFaces.size(); ++t)
            if (mesh.triangleFaces[t] < 1)
                fail(path, "triangle " + std::to_string(t) + " has face id " +
                               std::to_string(mesh.triangleFaces[t]) + " (face ids start at 1)");
    }
    if (!mesh.triangleNormals.empty()) {
        if (mesh.triangleNormals.size() != mesh.triangles.size())
            fail(path, "the mesh has " + std::to_string(mesh.triangles.size()) + " triangles but " +
                           std::to_string(mesh.triangleNormals.size()) + " normal triples");
        for (std::size_t t = 0; t < mesh.triangleNormals.size(); ++t)
            for (std::uint32_t index : mesh.triangleNormals[t])
                if (index >= mesh.normals.size())
                    fail(path, "triangle " + std::to_string(t) + " uses normal " +
                                   std::to_string(index) + " of " +
                                   std::to_string(mesh.normals.size()));
    }
}

// Appends text to a large buffer and hands it to stdio in big blocks: formatting number by
// number through iostreams is several times slower on meshes of millions of triangles.
class BufferedFile {
public:
    explicit BufferedFile(const std::string& path) : path_(path) {
        file_ = std::fopen(path.c_str(), "wb");
        if (!file_) fail(path, std::strerror(errno));
        buffer_.reserve(blockSize * 2);
    }
    ~BufferedFile() {
        if (file_) std::fclose(file_);
    }
    BufferedFile(const BufferedFile&) = delete;
    BufferedFile& operator=(const BufferedFile&) = delete;

    void append(std::string_view text) {
        buffer_.append(text);
        if (buffer_.size() >= blockSize) flush();
    }
    void append(char c) { buffer_.push_back(c); }
    // Shortest text that reads back to the same double.
    void append(double value) {
        char digits[32];
        auto [end, error] = std::to_chars(digits, digits + sizeof digits, value);
        if (error != std::errc()) fail(path_, "cannot format a number");
        buffer_.append(digits, end);
    }
    void append(std::uint64_t value) {
        char digits[24];
        auto [end, error] = std::to_chars(digits, digits + sizeof digits, value);
        if (error != std::errc()) fail(path_, "cannot format a number");
        buffer_.append(digits, end);
    }
    void appendLine() {
        buffer_.push_back('\n');
        if (buffer_.size() >= blockSize) flush();
    }

    void close() {
        flush();
        const int result = std::fclose(file_);
        file_ = nullptr;
        if (result != 0) fail(path_, std::strerror(errno));
    }

private:
    static constexpr std::size_t blockSize = 1 << 20;

    void flush() {
        if (buffer_.empty()) return;
        if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
            fail(path_, std::strerror(errno));
        buffer_.clear();
    }

    std::string path_;
    std::FILE* file_ = nullptr;
    std::string buffer_;
};

void writeObj(const Mesh& mesh, const std::string& path) {
    BufferedFile out(path);
    out.append("# NurbsLOD mesh: ");
    out.append(std::uint64_t{mesh.positions.size()});
    out.append(" vertices, ");
    out.append(std::uint64_t{mesh.triangles.size()});
    out.append(" triangles; group FaceN holds the triangles of B-rep face N");
    out.appendLine();
    for (const Point3& p : mesh.positions) {
        out.append("v ");
        out.append(p.x());
        out.append(' ');
        out.append(p.y());
        out.append(' ');
        out.append(p.z());
        out.appendLine();
    }
    const bool withNormals = !mesh.triangleNormals.empty();
    if (withNormals)
        for (const Vector3& n : mesh.normals) {
            out.append("vn ");
            out.append(n.x());
            out.append(' ');
            out.append(n.y());
            out.append(' ');
            out.append(n.z());
            out.appendLine();
        }

    // Triangles grouped by face id, in increasing order, each face's triangles in mesh order.
    std::vector<std::size_t> order(mesh.triangles.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const bool withFaces = !mesh.triangleFaces.empty();
    if (withFaces)
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return mesh.triangleFaces[a] < mesh.triangleFaces[b];
        });
    std::int64_t currentFace = -1;
    for (std::size_t t : order) {
        if (withFaces && mesh.triangleFaces[t] != currentFace) {
            currentFace = mesh.triangleFaces[t];
            out.append("g Face");
            out.append(static_cast<std::uint64_t>(currentFace));
            out.appendLine();
        }
        out.append('f');
        for (int corner = 0; corner < 3; ++corner) {
            out.append(' ');
            out.append(std::uint64_t{mesh.triangles[t][corner]} + 1);
            if (withNormals) {
                out.append("//");
                out.append(std::uint64_t{mesh.triangleNormals[t][corner]} + 1);
            }
        }
        out.appendLine();
    }
    out.close();
}

// OpenMesh keeps one normal per vertex; a Mesh position can carry a different normal in each
// face that meets there (a crease). Duplicating such positions would open the mesh, so the
// vertex gets the normalised sum of its normals instead: shared positions stay shared.
std::vector<Vector3> averagedVertexNormals(const Mesh& mesh) {
    std::vector<Vector3> sums(mesh.positions.size(), Vector3::Zero());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int corner = 0; corner < 3; ++corner)
            sums[mesh.triangles[t][corner]] += mesh.normals[mesh.triangleNormals[t][corner]];
    for (Vector3& n : sums) {
        const double length = n.norm();
        if (length > 0) n /= length;
    }
    return sums;
}

OpenMeshTriangleMesh toOpenMesh(const Mesh& mesh) {
    OpenMeshTriangleMesh result;
    result.request_vertex_normals();
    result.request_face_normals();
    std::vector<OpenMeshTriangleMesh::VertexHandle> vertices;
    vertices.reserve(mesh.positions.size());
    for (const Point3& p : mesh.positions)
        vertices.push_back(result.add_vertex(OpenMeshTriangleMesh::Point(p.x(), p.y(), p.z())));

    // A half-edge mesh refuses non-manifold and degenerate triangles; such a triangle gets
    // its own copies of its corners so that the file still holds every triangle.
    for (const auto& triangle : mesh.triangles) {
        const auto a = vertices[triangle[0]], b = vertices[triangle[1]], c = vertices[triangle[2]];
        if (result.add_face(a, b, c).is_valid()) continue;
        const auto a2 = result.add_vertex(result.point(a));
        const auto b2 = result.add_vertex(result.point(b));
        const auto c2 = result.add_vertex(result.point(c));
        result.add_face(a2, b2, c2);
    }

    // Geometric normals first: they serve the corner copies and a mesh without normals.
    result.update_face_normals();
    result.update_vertex_normals();
    if (!mesh.triangleNormals.empty()) {
        const std::vector<Vector3> normals = averagedVertexNormals(mesh);
        for (std::size_t v = 0; v < normals.size(); ++v)
            if (normals[v].squaredNorm() > 0)
                result.set_normal(vertices[v], OpenMeshTriangleMesh::Normal(
                                                   normals[v].x(), normals[v].y(), normals[v].z()));
    }
    return result;
}

void writeWithOpenMesh(const Mesh& mesh, const std::string& path, const std::string& extension) {
    // Opening the file ourselves first gives the user the system's reason when it fails;
    // OpenMesh only says "false".
    {
        std::FILE* probe = std::fopen(path.c_str(), "wb");
        if (!probe) fail(path, std::strerror(errno));
        std::fclose(probe);
    }
    const QuietOpenMesh quiet;
    const OpenMeshTriangleMesh openMesh = toOpenMesh(mesh);
    OpenMesh::IO::Options options;
    std::streamsize precision = 6;
    if (extension == ".ply") {
        options = OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::VertexNormal;
    } else if (extension == ".stl") {
        options = OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::FaceNormal;
    } else {
        options = OpenMesh::IO::Options::VertexNormal;
        precision = 17;
    }
    // OpenMesh picks its writer by the (lower-case) extension of the name it is given.
    bool written = false;
    const std::string lowerPath = std::filesystem::path(path).replace_extension(extension).string();
    if (lowerPath == path) {
        written = OpenMesh::IO::write_mesh(openMesh, path, options, precision);
    } else {
        std::ofstream stream(path, std::ios::binary);
        written = stream && OpenMesh::IO::write_mesh(openMesh, stream, extension.substr(1), options,
                                                     precision);
    }
    if (!written) fail(path, "OpenMesh could not write the " + extension.substr(1) + " file");
}

}  // namespace

void writeMesh(const Mesh& mesh, const std::string& path) {
    const std::string extension = lowerExtension(path);
    if (extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".off")
        fail(path, "unknown mesh format '" + extension + "' (expected .obj, .ply, .stl or .off)");
    checkConsistent(mesh, path);
    if (extension == ".obj")
        writeObj(mesh, path);
    else
        writeWithOpenMesh(mesh, path, extension);
}

}  // namespace nurbslod
