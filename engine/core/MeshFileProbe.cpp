#include "engine/core/MeshFileProbe.h"

#include "engine/io/InputFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace palpate {

namespace {

std::string lowerExtension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos) return {};
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

/// "N vertices, more than the M a mesh may have" when a declared count is beyond the limits of
/// engine/io/FileLimits.h (checked before anything is sized by it); "" otherwise.
std::string countProblem(long long vertices, long long faces) {
    if (vertices > 0 && std::uint64_t(vertices) > kMaxMeshVertices)
        return "declares " + std::to_string(vertices) + " vertices, more than the " +
               std::to_string(kMaxMeshVertices) + " a mesh may have";
    if (faces > 0 && std::uint64_t(faces) > kMaxMeshFaces)
        return "declares " + std::to_string(faces) + " faces, more than the " + std::to_string(kMaxMeshFaces) +
               " a mesh may have";
    return {};
}

/// Lines with content, comments ('#') removed.
std::vector<std::string> contentLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
    }
    return lines;
}

/// What is wrong with a record's coordinates, if anything: "" for finite coordinates a float holds.
struct CoordinateCheck {
    bool nonFinite = false;
    std::string outOfRange;  ///< the first coordinate beyond a float, as written
};

/// Counts the leading numbers of a record and checks them as coordinates: the mesh library reads
/// them into floats, and a value beyond a float's range (1e308) would make it lose its place in
/// the file silently.
std::size_t countNumbers(const std::string& line, CoordinateCheck* check = nullptr) {
    std::istringstream in(line);
    std::size_t n = 0;
    std::string token;
    while (in >> token) {
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end == token.c_str()) break;
        if (check && n < 3) {
            if (!std::isfinite(value)) check->nonFinite = true;
            else if (std::fabs(value) > double(std::numeric_limits<float>::max()) && check->outOfRange.empty())
                check->outOfRange = token.substr(0, 40);
        }
        ++n;
    }
    return n;
}

/// "" or the problem of a vertex record's coordinates, `where` naming the record.
std::string coordinateProblem(const CoordinateCheck& c, const std::string& where) {
    if (c.nonFinite) return "has NaN or infinite coordinates at " + where;
    if (!c.outOfRange.empty())
        return "has a coordinate out of range at " + where + ": " + c.outOfRange +
               " (a coordinate must be within +-3.4e38, a float's range; a tissue mesh is at most " +
               "100 m across anyway)";
    return {};
}

std::string probeOff(const std::string& text) {
    const auto lines = contentLines(text);
    if (lines.empty()) return "is not an OFF file (no header)";
    std::size_t at = 0;
    std::istringstream header(lines[0]);
    std::string magic;
    header >> magic;
    if (magic.find("OFF") == std::string::npos) return "is not an OFF file (missing 'OFF' header)";
    // CGAL's soup reader takes binary OFF's counts and corner counts as they come and skips no
    // face colours, so a binary OFF file is refused rather than half read (docs/meshes.md, "Reading").
    if (magic.find("BINARY") != std::string::npos || lines[0].find("BINARY") != std::string::npos)
        return "is a binary OFF file, which is not supported (export it as ASCII OFF, PLY or STL)";
    long long nv = -1, nf = -1;
    if (!(header >> nv >> nf)) {
        if (lines.size() < 2) return "is truncated: OFF header has no vertex and face counts";
        std::istringstream counts(lines[1]);
        if (!(counts >> nv >> nf)) return "has a malformed OFF header: no vertex and face counts";
        at = 2;
    } else {
        at = 1;
    }
    if (nv < 0 || nf < 0) return "has a malformed OFF header: negative counts";
    if (const std::string problem = countProblem(nv, nf); !problem.empty()) return problem;
    const std::size_t available = lines.size() - at;
    if (available < std::size_t(nv) + std::size_t(nf)) {
        return "is truncated: the OFF header declares " + std::to_string(nv) + " vertices and " +
               std::to_string(nf) + " faces, but only " + std::to_string(available) + " records follow";
    }
    for (long long i = 0; i < nv; ++i) {
        CoordinateCheck check;
        if (countNumbers(lines[at + std::size_t(i)], &check) < 3)
            return "has a malformed vertex record at OFF vertex " + std::to_string(i);
        if (std::string problem = coordinateProblem(check, "OFF vertex " + std::to_string(i)); !problem.empty())
            return problem;
    }
    // Faces: a corner count, then that many indices of existing vertices (the polygon-soup reader
    // only says that a record is malformed, not which).
    for (long long f = 0; f < nf; ++f) {
        std::istringstream record(lines[at + std::size_t(nv + f)]);
        long long corners = -1;
        if (!(record >> corners) || corners < 0)
            return "has a malformed face record at OFF face " + std::to_string(f);
        for (long long k = 0; k < corners; ++k) {
            long long index = -1;
            if (!(record >> index)) return "has a malformed face record at OFF face " + std::to_string(f);
            if (index < 0 || index >= nv)
                return "OFF face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                       ", but the file has " + std::to_string(nv) + " (corrupt or truncated)";
        }
    }
    return {};
}

std::string probeObj(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::size_t lineNo = 0, vertices = 0, faces = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream words(line);
        std::string key;
        if (!(words >> key)) continue;
        if (key == "v") {
            ++vertices;
            std::string rest;
            std::getline(words, rest);
            if (vertices > kMaxMeshVertices) return countProblem((long long)vertices, 0);
            CoordinateCheck check;
            if (countNumbers(rest, &check) < 3) return "has a malformed vertex at line " + std::to_string(lineNo);
            if (std::string problem = coordinateProblem(check, "line " + std::to_string(lineNo)); !problem.empty())
                return problem;
        } else if (key == "f") {
            ++faces;
            if (faces > kMaxMeshFaces) return countProblem(0, (long long)faces);
            std::size_t corners = 0;
            std::string token;
            while (words >> token) {
                if (token.empty() || !(std::isdigit((unsigned char)token[0]) || token[0] == '-'))
                    return "has a malformed face at line " + std::to_string(lineNo);
                ++corners;
            }
            if (corners < 3) return "has a face with fewer than 3 corners at line " + std::to_string(lineNo);
        }
    }
    if (vertices == 0) return "has no vertices ('v' lines)";
    if (faces == 0) return "has no faces ('f' lines)";
    return {};
}

std::string probeStl(const std::string& bytes) {
    // A binary header may begin with "solid" too (some exporters write it): a file whose size is
    // exactly what its triangle count declares is binary.
    std::uint32_t declared = 0;
    if (bytes.size() >= 84) std::memcpy(&declared, bytes.data() + 80, 4);
    const bool exactBinary = bytes.size() >= 84 && bytes.size() == 84ull + 50ull * declared;
    const bool looksAscii = !exactBinary && bytes.size() >= 5 && bytes.compare(0, 5, "solid") == 0 &&
                            bytes.find("facet") != std::string::npos;
    if (looksAscii) {
        if (bytes.find("endsolid") == std::string::npos) return "is truncated: ASCII STL without 'endsolid'";
        return {};
    }
    if (bytes.size() < 84) return "is truncated: shorter than a binary STL header (84 bytes)";
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (const std::string problem = countProblem(0, count); !problem.empty()) return problem;
    const std::uint64_t expected = 84ull + 50ull * count;
    if (bytes.size() < expected)
        return "is truncated: binary STL declares " + std::to_string(count) + " triangles (" +
               std::to_string(expected) + " bytes) but has " + std::to_string(bytes.size()) + " bytes";
    if (bytes.size() > expected + 1024)
        return "is not a binary STL: it declares " + std::to_string(count) + " triangles but has " +
               std::to_string(bytes.size()) + " bytes";
    for (std::uint32_t t = 0; t < count; ++t)
        for (int k = 3; k < 12; ++k) {  // skip the facet normal; check the three vertices
            float value = 0.0f;
            std::memcpy(&value, bytes.data() + 84 + 50ull * t + 4ull * std::size_t(k), 4);
            if (!std::isfinite(value))
                return "has NaN or infinite coordinates in triangle " + std::to_string(t);
        }
    return {};
}

std::string probePly(const std::string& bytes) {
    if (bytes.compare(0, 3, "ply") != 0) return "is not a PLY file (missing 'ply' magic)";
    const auto endHeader = bytes.find("end_header");
    if (endHeader == std::string::npos) return "is truncated: PLY header has no 'end_header'";
    std::istringstream header(bytes.substr(0, endHeader));
    std::string line, format;
    long long nv = -1, nf = -1;
    std::size_t vertexBytes = 0;
    std::string current;
    while (std::getline(header, line)) {
        std::istringstream w(line);
        std::string key;
        w >> key;
        if (key == "format") w >> format;
        else if (key == "element") {
            long long count = 0;
            w >> current >> count;
            if (current == "vertex") nv = count;
            if (current == "face") nf = count;
        } else if (key == "property" && current == "vertex") {
            std::string type;
            w >> type;
            if (type == "double" || type == "float64") vertexBytes += 8;
            else if (type == "float" || type == "float32" || type == "int" || type == "uint" || type == "int32" ||
                     type == "uint32")
                vertexBytes += 4;
            else if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
                vertexBytes += 2;
            else vertexBytes += 1;
        }
    }
    if (nv < 0 || nf < 0) return "has a PLY header without vertex or face elements";
    if (const std::string problem = countProblem(nv, nf); !problem.empty()) return problem;
    std::size_t bodyStart = bytes.find('\n', endHeader);
    bodyStart = bodyStart == std::string::npos ? bytes.size() : bodyStart + 1;
    if (format == "ascii") {
        const auto lines = contentLines(bytes.substr(bodyStart));
        if (lines.size() < std::size_t(nv + nf))
            return "is truncated: the PLY header declares " + std::to_string(nv) + " vertices and " +
                   std::to_string(nf) + " faces, but only " + std::to_string(lines.size()) + " records follow";
        for (long long i = 0; i < nv; ++i) {
            CoordinateCheck check;
            countNumbers(lines[std::size_t(i)], &check);
            if (std::string problem = coordinateProblem(check, "PLY vertex " + std::to_string(i)); !problem.empty())
                return problem;
        }
        return {};
    }
    // Binary: each face is at least a count byte and three 32-bit indices.
    const std::uint64_t minimum = std::uint64_t(nv) * vertexBytes + std::uint64_t(nf) * 13ull;
    if (bytes.size() - bodyStart < minimum)
        return "is truncated: the binary PLY body has " + std::to_string(bytes.size() - bodyStart) +
               " bytes, at least " + std::to_string(minimum) + " expected";
    return {};
}

/// OpenMesh's own format: "OM", a mesh type, a version, then the vertex and face counts (32-bit,
/// little-endian); the rest is OpenMesh's to check.
std::string probeOm(const std::string& bytes) {
    if (bytes.size() < 12 || bytes.compare(0, 2, "OM") != 0) return "is not an OpenMesh .om file (missing 'OM' header)";
    std::uint32_t vertices = 0, faces = 0;
    std::memcpy(&vertices, bytes.data() + 4, 4);
    std::memcpy(&faces, bytes.data() + 8, 4);
    return countProblem((long long)vertices, (long long)faces);
}

}  // namespace

std::string probeMeshFile(const std::string& path) {
    std::string error;
    const std::optional<std::string> bytes = readInputFile(path, kMeshFile, error);
    if (!bytes) return error.compare(0, path.size() + 2, path + ": ") == 0 ? error.substr(path.size() + 2) : error;
    return probeMeshBytes(*bytes, lowerExtension(path));
}

std::string probeMeshBytes(const std::string& bytes, const std::string& ext) {
    const bool textFormat = ext == "obj" || ext == "off";
    if (textFormat && bytes.find('\0') != std::string::npos)
        return "contains binary data where a text " + ext + " file was expected (corrupt or not a mesh)";
    if (ext == "off") return probeOff(bytes);
    if (ext == "obj") return probeObj(bytes);
    if (ext == "stl") return probeStl(bytes);
    if (ext == "ply") return probePly(bytes);
    if (ext == "om") return probeOm(bytes);
    return "has an unsupported extension '." + ext + "' (use .obj, .off, .ply, .stl or .om)";
}

}  // namespace palpate
