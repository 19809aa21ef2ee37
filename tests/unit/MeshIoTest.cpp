#include <gtest/gtest.h>

// MeshIO.hh before the mesh type, so that OpenMesh's readers register.
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/MeshWriter.hpp"
#include "io/ObjMeshReader.hpp"

using nurbslod::Mesh;
using nurbslod::MeshReadError;
using nurbslod::parseObjMesh;
using nurbslod::Point3;
using nurbslod::readObjMesh;
using nurbslod::Vector3;
using nurbslod::writeMesh;

namespace {

// A unit cube, 12 triangles on 6 faces, positions shared between faces, one normal per face:
// the corners carry a different normal in each face that meets there.
Mesh cubeMesh() {
    Mesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back(Point3(i & 1, (i >> 1) & 1, (i >> 2) & 1) * 1.1 +
                                 Point3(0.1, 1.0 / 3.0, -2e-17));
    // each side: outward normal and its corners counter-clockwise seen from outside
    const std::vector<std::pair<Vector3, std::array<std::uint32_t, 4>>> sides = {
        {Vector3(-1, 0, 0), {0, 4, 6, 2}}, {Vector3(1, 0, 0), {1, 3, 7, 5}},
        {Vector3(0, -1, 0), {0, 1, 5, 4}}, {Vector3(0, 1, 0), {2, 6, 7, 3}},
        {Vector3(0, 0, -1), {0, 2, 3, 1}}, {Vector3(0, 0, 1), {4, 5, 7, 6}},
    };
    // faces listed out of order, to check that the OBJ groups come out sorted
    const std::array<int, 6> faceIds = {3, 1, 6, 2, 5, 4};
    for (std::size_t s = 0; s < sides.size(); ++s) {
        const auto& [normal, c] = sides[s];
        mesh.normals.push_back(normal);
        const auto n = static_cast<std::uint32_t>(mesh.normals.size() - 1);
        mesh.triangles.push_back({c[0], c[1], c[2]});
        mesh.triangles.push_back({c[0], c[2], c[3]});
        mesh.triangleNormals.push_back({n, n, n});
        mesh.triangleNormals.push_back({n, n, n});
        mesh.triangleFaces.push_back(faceIds[s]);
        mesh.triangleFaces.push_back(faceIds[s]);
    }
    return mesh;
}

class TemporaryDirectory {
public:
    TemporaryDirectory() {
        path_ = std::filesystem::temp_directory_path() /
                ("nurbslod_mesh_io_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(path_);
    }
    ~TemporaryDirectory() { std::filesystem::remove_all(path_); }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

using FaceTriangle = std::tuple<int, std::uint32_t, std::uint32_t, std::uint32_t>;

std::vector<FaceTriangle> sortedFaceTriangles(const Mesh& mesh) {
    std::vector<FaceTriangle> result;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        result.emplace_back(mesh.triangleFaces[t], mesh.triangles[t][0], mesh.triangles[t][1],
                            mesh.triangles[t][2]);
    std::sort(result.begin(), result.end());
    return result;
}

std::string errorOf(const std::string& objText) {
    try {
        parseObjMesh(objText, "test.obj");
    } catch (const MeshReadError& error) {
        return error.what();
    }
    return "no error";
}

using OpenMeshTriangleMesh = OpenMesh::TriMesh_ArrayKernelT<>;

}  // namespace

TEST(MeshIo, ObjRoundTripKeepsPositionsTrianglesAndFaces) {
    TemporaryDirectory directory;
    const Mesh mesh = cubeMesh();
    const std::string path = directory.file("cube.obj");
    writeMesh(mesh, path);
    const Mesh back = readObjMesh(path);

    ASSERT_EQ(back.positions.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        EXPECT_EQ(back.positions[i], mesh.positions[i]) << "position " << i;  // bit for bit
    EXPECT_EQ(sortedFaceTriangles(back), sortedFaceTriangles(mesh));
    ASSERT_EQ(back.triangleNormals.size(), mesh.triangles.size());
    for (std::size_t t = 0; t < back.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Vector3 normal = back.normals[back.triangleNormals[t][k]];
            const Point3 a = back.positions[back.triangles[t][0]];
            const Vector3 geometric = (back.positions[back.triangles[t][1]] - a)
                                          .cross(back.positions[back.triangles[t][2]] - a)
                                          .normalized();
            EXPECT_NEAR(normal.dot(geometric), 1.0, 1e-12) << "triangle " << t;
        }

    // one "v" per shared position, groups in increasing face order
    const std::string text = readText(path);
    std::istringstream lines(text);
    std::string line;
    std::size_t vertexLines = 0;
    std::vector<std::string> groups;
    while (std::getline(lines, line)) {
        if (line.rfind("v ", 0) == 0) ++vertexLines;
        if (line.rfind("g ", 0) == 0) groups.push_back(line);
    }
    EXPECT_EQ(vertexLines, mesh.positions.size());
    EXPECT_EQ(groups, (std::vector<std::string>{"g Face1", "g Face2", "g Face3", "g Face4",
                                                "g Face5", "g Face6"}));
}

TEST(MeshIo, ObjWithoutNormalsWritesPlainFaces) {
    TemporaryDirectory directory;
    Mesh mesh = cubeMesh();
    mesh.normals.clear();
    mesh.triangleNormals.clear();
    const std::string path = directory.file("plain.OBJ");  // extension case does not matter
    writeMesh(mesh, path);
    EXPECT_EQ(readText(path).find("//"), std::string::npos);
    const Mesh back = readObjMesh(path);
    EXPECT_TRUE(back.normals.empty());
    EXPECT_EQ(sortedFaceTriangles(back), sortedFaceTriangles(mesh));
}

TEST(MeshIo, PlyStlOffAreReadBackByOpenMesh) {
    TemporaryDirectory directory;
    const Mesh mesh = cubeMesh();
    for (const std::string name : {"cube.ply", "cube.stl", "cube.off", "CUBE.PLY"}) {
        const std::string path = directory.file(name);
        writeMesh(mesh, path);
        OpenMeshTriangleMesh back;
        OpenMesh::IO::Options options;
        std::string extension = std::filesystem::path(name).extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
        // OpenMesh's readers go by the lower-case extension
        const std::string copy = directory.file("copy" + extension);
        std::filesystem::copy_file(path, copy);
        ASSERT_TRUE(OpenMesh::IO::read_mesh(back, copy, options)) << name;
        std::filesystem::remove(copy);
        EXPECT_EQ(back.n_faces(), mesh.triangles.size()) << name;
        EXPECT_EQ(back.n_vertices(), mesh.positions.size()) << name;  // still shared
        EXPECT_EQ(back.n_edges(), 18u) << name;                       // closed cube
        const std::string text = readText(path);
        if (extension == ".ply") {
            EXPECT_EQ(text.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << name;
            EXPECT_NE(text.find("property float nx"), std::string::npos) << name;
        }
        if (extension == ".off") {
            EXPECT_EQ(text.rfind("NOFF", 0), 0u);  // with normals
        }
        if (extension == ".stl") {
            EXPECT_EQ(text.size(), 80u + 4u + 12u * 50u);  // binary: header, count, facets
        }
    }
}

TEST(MeshIo, NonManifoldTrianglesAreKeptInOpenMeshFormats) {
    TemporaryDirectory directory;
    Mesh mesh = cubeMesh();
    // a third triangle on an edge of the cube and a triangle with a repeated corner: a
    // half-edge mesh refuses both, the file must still hold them
    mesh.positions.push_back(Point3(5, 5, 5));
    mesh.triangles.push_back({0, 1, 8});
    mesh.triangles.push_back({2, 2, 8});
    mesh.triangleFaces.push_back(7);
    mesh.triangleFaces.push_back(7);
    mesh.normals.push_back(Vector3(0, 0, 1));
    mesh.triangleNormals.push_back({6, 6, 6});
    mesh.triangleNormals.push_back({6, 6, 6});
    const std::string path = directory.file("odd.off");
    writeMesh(mesh, path);
    // OpenMesh's reader would refuse them again, so count what the file says it holds
    std::istringstream text(readText(path));
    std::string magic;
    std::size_t vertexCount = 0, faceCount = 0;
    text >> magic >> vertexCount >> faceCount;
    EXPECT_EQ(magic, "NOFF");
    EXPECT_EQ(faceCount, mesh.triangles.size());
    EXPECT_GE(vertexCount, mesh.positions.size());
}

TEST(MeshIo, WriterNamesPathAndReason) {
    TemporaryDirectory directory;
    const Mesh mesh = cubeMesh();
    try {
        writeMesh(mesh, directory.file("cube.xyz"));
        FAIL() << "an unknown extension was accepted";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("cube.xyz"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("unknown mesh format"), std::string::npos);
    }
    for (const std::string name : {"no/such/dir/cube.obj", "no/such/dir/cube.ply"}) {
        try {
            writeMesh(mesh, directory.file(name));
            FAIL() << "wrote into a missing directory";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find("No such file"), std::string::npos)
                << error.what();
        }
    }
    Mesh broken = mesh;
    broken.triangles[3][1] = 99;
    EXPECT_THROW(writeMesh(broken, directory.file("broken.obj")), std::runtime_error);
    broken = mesh;
    broken.triangleFaces[0] = 0;
    EXPECT_THROW(writeMesh(broken, directory.file("broken.obj")), std::runtime_error);
}

TEST(MeshIo, ObjReaderUnderstandsAllFaceForms) {
    const Mesh mesh = parseObjMesh(
        "# comment\n"
        "mtllib x.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\r\n"
        "vt 0 0\nvn 0 0 1\n"
        "g Face3\n"
        "f 1 2 3\n"
        "f 1/1 3/1 4/1\n"
        "o Face1 with a comment\n"
        "usemtl red\n"
        "s off\n"
        "f 1//1 2//1 3//1\n"
        "f -4/1/1 -2/1/1 -1/1/1\n"
        "g Face2\n"
        "f 1 2 3 4\n",  // a quad: fanned into two triangles
        "forms.obj");
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[2], Point3(1, 1, 0));
    ASSERT_EQ(mesh.triangles.size(), 6u);
    EXPECT_EQ(mesh.triangleFaces, (std::vector<std::int32_t>{3, 3, 1, 1, 2, 2}));
    EXPECT_EQ(mesh.triangles[3], (std::array<std::uint32_t, 3>{0, 2, 3}));  // negative indices
    EXPECT_EQ(mesh.triangles[4], (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[5], (std::array<std::uint32_t, 3>{0, 2, 3}));
    EXPECT_TRUE(mesh.normals.empty());  // not every corner named a normal
    EXPECT_TRUE(mesh.triangleNormals.empty());
}

TEST(MeshIo, ObjReaderReportsLineOfMalformedInput) {
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_NE(errorOf(vertices + "f 1 2 3\n").find("test.obj:4: triangle outside a 'g FaceN'"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Other\nf 1 2 3\n").find(":5: triangle outside"),
              std::string::npos);
    EXPECT_NE(errorOf("v 0 0\n").find("test.obj:1: vertex with fewer than 3"), std::string::npos);
    EXPECT_NE(errorOf("v 0 x 0\n").find(":1: malformed vertex coordinate 'x'"), std::string::npos);
    EXPECT_NE(errorOf("v 0 nan 0\n").find("not finite"), std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1 2 4\n").find(":5: vertex index 4 out of range"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1 2 -4\n").find("vertex index -4 out of range"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1 0 2\n").find("vertex index 0 out of range"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1 2\n").find(":5: face with 2 vertices"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1 a 2\n").find("malformed vertex index 'a'"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face1\nf 1//2 2//2 3//2\n").find("normal index 2 out"),
              std::string::npos);
    EXPECT_NE(errorOf(vertices + "g Face0\nf 1 2 3\n").find("face numbers start at 1"),
              std::string::npos);
    EXPECT_EQ(errorOf(vertices + "g Face1\nf 1 2 3\n"), "no error");
}

TEST(MeshIo, ObjReaderNamesMissingFile) {
    try {
        readObjMesh("/nonexistent/mesh.obj");
        FAIL() << "read a missing file";
    } catch (const MeshReadError& error) {
        EXPECT_NE(std::string(error.what()).find("/nonexistent/mesh.obj"), std::string::npos);
    }
}
