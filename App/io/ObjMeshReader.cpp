#include "io/ObjMeshReader.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

namespace nurbslod {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Splits a line into whitespace-separated tokens without copying.
class Tokens {
public:
    explicit Tokens(std::string_view line) : rest_(line) {}

    std::optional<std::string_view> next() {
        std::size_t begin = 0;
        while (begin < rest_.size() && isSpace(rest_[begin])) ++begin;
        if (begin == rest_.size()) return std::nullopt;
        std::size_t end = begin;
        while (end < rest_.size() && !isSpace(rest_[end])) ++end;
        const std::string_view token = rest_.substr(begin, end - begin);
        rest_ = rest_.substr(end);
        return token;
    }

    std::string_view remainder() const { return rest_; }

private:
    std::string_view rest_;
};

std::string_view trim(std::string_view text) {
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

class ObjParser {
public:
    explicit ObjParser(const std::string& name) : name_(name) {}

    Mesh parse(std::string_view text) {
        std::size_t lineStart = 0;
        while (lineStart < text.size()) {
            std::size_t lineEnd = text.find('\n', lineStart);
            if (lineEnd == std::string_view::npos) lineEnd = text.size();
            ++lineNumber_;
            parseLine(text.substr(lineStart, lineEnd - lineStart));
            lineStart = lineEnd + 1;
        }
        if (!allCornersHaveNormals_ || mesh_.triangles.empty()) {
            mesh_.normals.clear();
            mesh_.triangleNormals.clear();
        }
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& reason) const {
        throw MeshReadError(name_ + ":" + std::to_string(lineNumber_) + ": " + reason);
    }

    void parseLine(std::string_view line) {
        Tokens tokens(line);
        const std::optional<std::string_view> keyword = tokens.next();
        if (!keyword || keyword->front() == '#') return;
        if (*keyword == "v")
            mesh_.positions.push_back(readVector(tokens, "vertex"));
        else if (*keyword == "vn")
            mesh_.normals.push_back(readVector(tokens, "normal"));
        else if (*keyword == "g" || *keyword == "o")
            readGroup(trim(tokens.remainder()));
        else if (*keyword == "f")
            readFace(tokens);
        // Everything else (vt, s, usemtl, mtllib, l, ...) carries nothing a Mesh holds.
    }

    double readNumber(std::string_view token, const char* what) const {
        if (!token.empty() && token.front() == '+') token.remove_prefix(1);
        double value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size())
            fail(std::string("malformed ") + what + " coordinate '" + std::string(token) + "'");
        if (!std::isfinite(value))
            fail(std::string(what) + " coordinate '" + std::string(token) + "' is not finite");
        return value;
    }

    Point3 readVector(Tokens& tokens, const char* what) const {
        Point3 result;
        for (int axis = 0; axis < 3; ++axis) {
            const std::optional<std::string_view> token = tokens.next();
            if (!token) fail(std::string(what) + " with fewer than 3 coordinates");
            result[axis] = readNumber(*token, what);
        }
        return result;
    }

    // As meshjudge: a name "FaceN..." selects face N, any other name leaves every group.
    void readGroup(std::string_view name) {
        currentFace_.reset();
        if (name.substr(0, 4) != "Face") return;
        name.remove_prefix(4);
        std::size_t end = 0;
        while (end < name.size() && !isSpace(name[end])) ++end;
        std::string_view digits = name.substr(0, end);
        if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
        long long face = 0;
        const auto [last, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), face);
        if (digits.empty() || error != std::errc() || last != digits.data() + digits.size()) return;
        currentFace_ = face;
    }

    // One index of an "f" corner: 1-based, or negative counting back from the last element.
    std::uint32_t resolveIndex(std::string_view token, std::size_t count, const char* what) const {
        long long index = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), index);
        if (token.empty() || error != std::errc() || end != token.data() + token.size())
            fail(std::string("malformed ") + what + " index '" + std::string(token) + "'");
        const long long count64 = static_cast<long long>(count);
        const long long resolved = index > 0 ? index - 1 : count64 + index;
        if (index == 0 || resolved < 0 || resolved >= count64)
            fail(std::string(what) + " index " + std::to_string(index) + " out of range (" +
                 std::to_string(count) + " " + what + "s so far)");
        if (resolved > std::numeric_limits<std::uint32_t>::max()) fail("too many vertices");
        return static_cast<std::uint32_t>(resolved);
    }

    void readFace(Tokens& tokens) {
        corners_.clear();
        cornerNormals_.clear();
        bool faceHasAllNormals = true;
        while (const std::optional<std::string_view> token = tokens.next()) {
            // a, a/b, a//c or a/b/c: position, texture coordinate, normal
            const std::size_t firstSlash = token->find('/');
            corners_.push_back(
                resolveIndex(token->substr(0, firstSlash), mesh_.positions.size(), "vertex"));
            std::optional<std::uint32_t> normal;
            if (firstSlash != std::string_view::npos) {
                const std::size_t secondSlash = token->find('/', firstSlash + 1);
                if (secondSlash != std::string_view::npos && secondSlash + 1 < token->size())
                    normal = resolveIndex(token->substr(secondSlash + 1), mesh_.normals.size(),
                                          "normal");
            }
            if (normal)
                cornerNormals_.push_back(*normal);
            else
                faceHasAllNormals = false;
        }
        if (corners_.size() < 3)
            fail("face with " + std::to_string(corners_.size()) + " vertices (at least 3)");
        if (!currentFace_) fail("triangle outside a 'g FaceN' group");
        if (*currentFace_ < 1 || *currentFace_ > std::numeric_limits<std::int32_t>::max())
            fail("group Face" + std::to_string(*currentFace_) + ": face numbers start at 1");
        if (!faceHasAllNormals) allCornersHaveNormals_ = false;
        for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {
            mesh_.triangles.push_back({corners_[0], corners_[k], corners_[k + 1]});
            mesh_.triangleFaces.push_back(static_cast<std::int32_t>(*currentFace_));
            if (allCornersHaveNormals_)
                mesh_.triangleNormals.push_back(
                    {cornerNormals_[0], cornerNormals_[k], cornerNormals_[k + 1]});
        }
    }

    std::string name_;
    std::size_t lineNumber_ = 0;
    Mesh mesh_;
    std::optional<long long> currentFace_;
    bool allCornersHaveNormals_ = true;
    std::vector<std::uint32_t> corners_, cornerNormals_;
};

}  // namespace

Mesh parseObjMesh(std::string_view text, const std::string& name) {
    return ObjParser(name).parse(text);
}

Mesh readObjMesh(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw MeshReadError("cannot read mesh " + path + ": " + std::strerror(errno));
    std::string text;
    char block[1 << 16];
    std::size_t got = 0;
    while ((got = std::fread(block, 1, sizeof block, file)) > 0) text.append(block, got);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) throw MeshReadError("cannot read mesh " + path + ": read error");
    return parseObjMesh(text, path);
}

}  // namespace nurbslod
