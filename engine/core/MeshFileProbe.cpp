#include "engine/core/MeshFileProbe.h"

#include "base/io/InputFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
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
/// base/io/FileLimits.h (checked before anything is sized by it); "" otherwise.
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
    // Exactly "OFF": the soup reader reads the counts from whatever follows "OFF" (so
    // "OFF\x02400000300" must not pass), and it reads past a short record of the variants with
    // colours, normals or texture coordinates (COFF, NOFF, STOFF, 4OFF, nOFF), which are refused.
    if (magic != "OFF") {
        if (magic.size() > 3 && magic.size() <= 7 && magic.compare(magic.size() - 3, 3, "OFF") == 0)
            return "is an OFF variant ('" + magic + "') that is not supported (export it as plain OFF, PLY or STL)";
        return "is not an OFF file (the header's first word is '" + magic.substr(0, 20) + "', not OFF)";
    }
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
    // Bytes after the last triangle: a few are padding some exporters write (noted by the reader);
    // a whole triangle's worth or more means the header understates the count, and reading only
    // what it declares would silently drop the rest of the mesh.
    if (bytes.size() >= expected + 50)
        return "declares " + std::to_string(count) + " triangles in its header, but " +
               std::to_string((bytes.size() - expected) / 50) + " more triangles' worth of bytes follow (" +
               std::to_string(bytes.size()) +
               " bytes in all): the header understates the count, or this is not a "
               "binary STL";
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
    // The header ends at the first line whose first word is "end_header", as the soup reader
    // reads it ("end_header\xd5..." is not the end).
    std::size_t endHeader = std::string::npos, bodyStart = bytes.size();
    for (std::size_t lineStart = 0; lineStart < bytes.size();) {
        std::size_t lineEnd = bytes.find('\n', lineStart);
        if (lineEnd == std::string::npos) lineEnd = bytes.size();
        std::istringstream words(bytes.substr(lineStart, std::min<std::size_t>(lineEnd - lineStart, 200)));
        std::string first;
        if (words >> first && first == "end_header") {
            endHeader = lineStart;
            bodyStart = std::min(bytes.size(), lineEnd + 1);
            break;
        }
        lineStart = lineEnd + 1;
    }
    if (endHeader == std::string::npos) return "is truncated: PLY header has no 'end_header'";
    std::istringstream header(bytes.substr(0, endHeader));
    std::string line, format;
    long long nv = -1, nf = -1;
    std::size_t vertexBytes = 0;
    std::string current;
    // The header's grammar is checked in full: CGAL's PLY reader takes a property before any
    // element, or a list without its types, for granted.
    static const char* const kTypes[] = {"char",  "int8",   "uchar", "uint8",   "short",   "int16",  "ushort",
                                         "uint16", "int",   "int32", "uint",    "uint32",  "float",  "float32",
                                         "double", "float64"};
    auto knownType = [](const std::string& t) {
        return std::any_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; });
    };
    std::size_t headerLine = 0;
    std::vector<std::string> elements;
    long long records = 0;
    bool formatSeen = false;
    while (std::getline(header, line)) {
        ++headerLine;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream w(line);
        std::string key;
        w >> key;
        const std::string where = "has a malformed PLY header at line " + std::to_string(headerLine);
        if (headerLine == 1) {
            if (key != "ply") return where;
            continue;
        }
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            if (formatSeen) return where + " (a second format line)";
            formatSeen = true;
            w >> format;
            if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") return where;
        } else if (key == "element") {
            std::string countText, rest;
            if (!(w >> current >> countText) || (w >> rest)) return where;
            char* end = nullptr;
            errno = 0;
            const long long count = std::strtoll(countText.c_str(), &end, 10);
            if (*end != '\0' || errno == ERANGE || count < 0) return where;
            // The soup reader walks every element's declared count, at the end of the data too.
            if (std::find(elements.begin(), elements.end(), current) != elements.end())
                return where + " (element '" + current.substr(0, 20) + "' declared twice)";
            elements.push_back(current);
            if (current == "halfedge") return "has a PLY 'halfedge' element, which is not supported";
            if (std::uint64_t(count) > kMaxMeshFaces) return countProblem(0, count);
            records += count;
            if (current == "vertex") nv = count;
            if (current == "face") nf = count;
        } else if (key == "property") {
            std::string type, name, rest;
            if (current.empty() || !(w >> type) || (!knownType(type) && type != "list")) return where;
            if (type == "list") {
                std::string countType, indexType;
                if (!(w >> countType >> indexType >> name) || !knownType(countType) || !knownType(indexType))
                    return where;
                // The soup reader sizes a list by its count before it reads it: a 32-bit or a
                // floating-point count could ask for gigabytes.
                static const char* const kSmallCounts[] = {"char", "int8", "uchar", "uint8", "short", "int16", "ushort", "uint16"};
                if (std::none_of(std::begin(kSmallCounts), std::end(kSmallCounts), [&](const char* k) { return countType == k; }))
                    return "has a PLY list counted by a '" + countType + "' at header line " + std::to_string(headerLine) +
                           ", which is not supported (a count of 8 or 16 bits, such as uchar, is)";
            } else if (!(w >> name)) {
                return where;
            }
            if (w >> rest) return where;
            // The soup reader reads a vertex's x, y and z as floating point, whatever the header says.
            if ((current == "vertex" || current == "vertices") && (name == "x" || name == "y" || name == "z") &&
                type != "float" && type != "float32" && type != "double" && type != "float64")
                return "has a PLY vertex coordinate '" + name + "' of type '" + type +
                       "', which is not supported (float or double is)";
        } else {
            return where;
        }
        if (key == "property" && current == "vertex") {
            std::istringstream again(line);
            std::string type;
            again >> type >> type;
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
    if (format == "ascii") {
        const auto lines = contentLines(bytes.substr(bodyStart));
        if (lines.size() < std::size_t(records))
            return "is truncated: the PLY header declares " + std::to_string(nv) + " vertices and " +
                   std::to_string(nf) + " faces" + (records > nv + nf ? " (and other records)" : "") + ", but only " +
                   std::to_string(lines.size()) + " records follow";
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

/// A little-endian integer of `size` bytes at `at`, sign-extended when `isSigned`.
long long readLittleEndian(const std::string& bytes, std::size_t at, std::size_t size, bool isSigned) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < size; ++i) v |= std::uint64_t((unsigned char)bytes[at + i]) << (8 * i);
    if (isSigned && size < 8 && (v >> (8 * size - 1)) & 1u) v |= ~std::uint64_t(0) << (8 * size);
    return (long long)v;
}

/// OpenMesh's own format: "OM", a mesh type, a version, the vertex, face and edge counts (32-bit,
/// little-endian), then chunks, each a 16-bit header and its data. OpenMesh's reader asserts on a
/// chunk of the wrong shape and stores any index it finds, so every chunk is walked here first:
/// only the chunks OpenMesh writes for a mesh's geometry are accepted, each must fit the file,
/// and every index in a topology chunk must be in range.
std::string probeOm(const std::string& bytes) {
    if (bytes.size() < 12 || bytes.compare(0, 2, "OM") != 0) return "is not an OpenMesh .om file (missing 'OM' header)";
    // The mesh type OpenMesh's own check of a file (can_u_read) demands; its stream reader skips it.
    const char meshType = bytes[2];
    if (meshType != 'T' && meshType != 'Q' && meshType != 'P')
        return "is not an OpenMesh .om file (unknown mesh type in the header)";
    std::uint32_t vertices = 0, faces = 0, edges = 0;
    std::memcpy(&vertices, bytes.data() + 4, 4);
    std::memcpy(&faces, bytes.data() + 8, 4);
    if (const std::string problem = countProblem((long long)vertices, (long long)faces); !problem.empty())
        return problem;
    if (bytes.size() < 16) return {};  // no chunks: OpenMesh reads no mesh, which the reader names
    std::memcpy(&edges, bytes.data() + 12, 4);
    if (edges > 3 * kMaxMeshFaces) return "declares " + std::to_string(edges) + " edges, more than a mesh may have";
    const bool version2 = ((unsigned char)bytes[3] >> 5) >= 2;
    const long long halfedges = 2ll * edges;
    std::size_t at = 16;
    bool positionsRead = false, halfedgesRead = false;
    auto truncated = [] { return std::string("is truncated: an .om chunk is cut off"); };
    auto unsupported = [](unsigned entity, unsigned type) {
        return "has an .om chunk this reader does not support (entity " + std::to_string(entity) + ", type " +
               std::to_string(type) + ")";
    };
    while (at < bytes.size()) {
        if (bytes.size() - at < 2) return truncated();
        const unsigned h = unsigned((unsigned char)bytes[at]) | unsigned((unsigned char)bytes[at + 1]) << 8;
        at += 2;
        const unsigned named = (h >> 1) & 1u, entity = (h >> 2) & 7u, type = (h >> 5) & 15u;
        const unsigned isFloat = (h >> 10) & 1u, dim = ((h >> 11) & 7u) + 1, bits = (h >> 14) & 3u;
        if (entity == 7) return {};  // the sentinel
        if (named) return "has a named .om property, which this reader does not support";
        const std::size_t intSize = std::size_t(1) << bits;
        const std::size_t left = bytes.size() - at;
        // Fixed-size records: `count` records of `record` bytes.
        auto fixed = [&](std::uint64_t count, std::uint64_t record) -> std::string {
            if (count * record > left) return truncated();
            at += std::size_t(count * record);
            return {};
        };
        // Indices of `count` records of `perRecord` indices, each within [low, high).
        auto indices = [&](std::uint64_t count, int perRecord, const long long* low, const long long* high) -> std::string {
            if (count * std::uint64_t(perRecord) * intSize > left) return truncated();
            for (std::uint64_t r = 0; r < count; ++r)
                for (int k = 0; k < perRecord; ++k) {
                    const long long v = readLittleEndian(bytes, at, intSize, true);
                    at += intSize;
                    if (v < low[k] || v >= high[k])
                        return "is corrupt: an .om topology chunk refers to element " + std::to_string(v) +
                               " of " + std::to_string(high[k]);
                }
            return {};
        };
        std::string problem;
        const bool float3 = isFloat && bits == 0 && dim == 3;
        if (entity == 0 && type == 0 && float3 && !positionsRead) {  // positions: they make the vertices
            positionsRead = true;
            problem = fixed(vertices, 12);
        }
        else if (entity == 0 && type == 1 && float3)
            problem = fixed(vertices, 12);      // normals
        else if (entity == 0 && type == 2 && isFloat && bits == 0 && dim == 2) problem = fixed(vertices, 8);
        else if (entity == 0 && type == 4 && dim == 3 && bits == 0 && !isFloat) problem = fixed(vertices, 3);
        else if (entity == 2 && type == 1 && float3) problem = fixed(faces, 12);
        else if (entity == 2 && type == 4 && dim == 3 && bits == 0 && !isFloat) problem = fixed(faces, 3);
        // A vertex's halfedge is stored into the vertex, which the positions must have made.
        else if (entity == 0 && type == 7 && version2 && positionsRead) {
            const long long low[] = {-1}, high[] = {halfedges};
            problem = indices(vertices, 1, low, high);
        } else if (entity == 2 && type == 7 && version2) {
            const long long low[] = {0}, high[] = {halfedges};
            problem = indices(faces, 1, low, high);
        } else if (entity == 6 && type == 7 && version2 && !halfedgesRead) {
            // Each record makes an edge; its next halfedges are linked back (prev), so they must exist.
            halfedgesRead = true;
            const long long low[] = {0, 0, -1, 0, 0, -1};
            const long long high[] = {halfedges, vertices, faces, halfedges, vertices, faces};
            problem = indices(edges, 6, low, high);
        } else if (entity == 2 && type == 7 && !version2 && meshType != 'P') {
            const long long low[] = {0, 0, 0, 0}, high[] = {vertices, vertices, vertices, vertices};
            problem = indices(faces, meshType == 'T' ? 3 : 4, low, high);
        } else {
            return unsupported(entity, type);
        }
        if (!problem.empty()) return problem;
    }
    return {};
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
