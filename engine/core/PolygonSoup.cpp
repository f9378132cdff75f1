#include "engine/core/PolygonSoup.h"

#include "engine/core/CountedText.h"

#include "engine/core/MeshFileProbe.h"
#include "base/io/FileLimits.h"
#include "base/io/InputFile.h"

// Only CGAL's soup readers: they read points and polygons as written, without building a
// half-edge structure that would split or drop faulty faces (docs/meshes.md, "Reading").
#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>

namespace palpate {

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using CgalPolygons = std::vector<std::vector<std::size_t>>;

/// Above this many corners a concave polygon is fanned instead of ear-clipped, and after this many
/// ear tests in one file every further concave polygon is: ear clipping is quadratic or worse in
/// the corners, and a hostile file must not hang the loader.
constexpr std::size_t kMaxEarClipCorners = 512;
constexpr std::size_t kEarTestBudget = 200'000'000;

std::string lowerExtension(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext;
}

/// The tolerances every text format shares, applied in place: a UTF-8 byte-order mark, trailing
/// NUL bytes (editors and transfer tools pad files with them), CR LF or lone CR line ends (to LF)
/// and tabs (to spaces: CGAL's OBJ face parser only skips to the next ' ').
void sanitiseText(std::string& text, std::vector<std::string>& notes) {
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {
        text.erase(0, 3);
        notes.push_back("UTF-8 byte-order mark ignored");
    }
    std::size_t nuls = 0;
    while (!text.empty() && text.back() == '\0') {
        text.pop_back();
        ++nuls;
    }
    if (nuls) notes.push_back(countedText(nuls, "trailing NUL byte", "trailing NUL bytes") + " ignored");

    std::size_t crlf = 0, cr = 0, lf = 0, tabs = 0;
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\r') {
            if (i + 1 < text.size() && text[i + 1] == '\n') {
                ++crlf;
                ++i;
            } else {
                ++cr;
            }
            out += '\n';
        } else {
            if (c == '\n') ++lf;
            if (c == '\t') ++tabs;
            out += c == '\t' ? ' ' : c;
        }
    }
    text.swap(out);
    std::vector<std::string> kinds;
    if (crlf) kinds.push_back("CR LF");
    if (lf) kinds.push_back("LF");
    if (cr) kinds.push_back("CR");
    if (kinds.size() > 1) {
        std::string list = kinds[0];
        for (std::size_t k = 1; k < kinds.size(); ++k) list += (k + 1 == kinds.size() ? " and " : ", ") + kinds[k];
        notes.push_back("mixed line ends (" + list + ") read as LF");
    } else if (crlf) {
        notes.push_back("CR LF line ends read as LF");
    } else if (cr) {
        notes.push_back("CR line ends read as LF");
    }
    if (tabs) notes.push_back(countedText(tabs, "tab", "tabs") + " read as spaces");
}

/// The OBJ pre-scan CGAL's reader lacks: it names the line of a bad face, resolves negative
/// (relative) indices, drops the texture and normal indices of a corner ("7/1/3", "7//3") and the
/// records the soup has no use for, so that CGAL reads only "v" and plain "f" records.
std::string prescanObj(std::string& text, std::vector<std::string>& notes) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    std::size_t lineNo = 0, vertices = 0;
    std::size_t comments = 0, grouping = 0, polylines = 0, attributes = 0, relative = 0, cornerIndices = 0, unknown = 0;
    std::string firstUnknown;
    std::size_t maxIndex = 0, maxIndexLine = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (const std::size_t hash = line.find('#'); hash != std::string::npos) {
            line.resize(hash);
            ++comments;
        }
        std::istringstream words(line);
        std::string key;
        if (!(words >> key)) {
            out << '\n';
            continue;
        }
        if (key == "v") {
            ++vertices;
            out << line << '\n';
        } else if (key == "f") {
            out << 'f';
            std::string corner;
            std::size_t corners = 0;
            while (words >> corner) {
                char* end = nullptr;
                errno = 0;
                const long long index = std::strtoll(corner.c_str(), &end, 10);
                if (end == corner.c_str() || (*end != '\0' && *end != '/') || errno == ERANGE)
                    return "line " + std::to_string(lineNo) + ": a malformed face corner '" + corner.substr(0, 40) +
                           "'";
                if (*end == '/') ++cornerIndices;
                long long absolute = index;
                if (index == 0)
                    return "line " + std::to_string(lineNo) + ": a face refers to vertex 0 (OBJ counts from 1)";
                if (index < 0) {
                    ++relative;
                    absolute = (long long)vertices + index + 1;
                    if (absolute < 1)
                        return "line " + std::to_string(lineNo) + ": a face refers to vertex " + std::to_string(index) +
                               " (relative), but only " + std::to_string(vertices) + " vertices precede it";
                }
                if (std::size_t(absolute) > maxIndex) {
                    maxIndex = std::size_t(absolute);
                    maxIndexLine = lineNo;
                }
                out << ' ' << absolute;
                ++corners;
            }
            if (corners < 3)
                return "line " + std::to_string(lineNo) + ": a face with " + countedText(corners, "corner", "corners") +
                       " (at least 3 are needed)";
            out << '\n';
        } else if (key == "o" || key == "g" || key == "s" || key == "usemtl" || key == "mtllib") {
            ++grouping;
            out << '\n';
        } else if (key == "vt" || key == "vn" || key == "vp") {
            ++attributes;
            out << '\n';
        } else if (key == "l" || key == "p") {
            ++polylines;
            out << '\n';
        } else {
            if (!unknown) firstUnknown = "line " + std::to_string(lineNo) + ": '" + key.substr(0, 20) + "'";
            ++unknown;
            out << '\n';
        }
    }
    if (maxIndex > vertices)
        return "line " + std::to_string(maxIndexLine) + ": a face refers to vertex " + std::to_string(maxIndex) +
               ", but the file has " + std::to_string(vertices);
    text = out.str();
    if (comments) notes.push_back(countedText(comments, "comment", "comments") + " ignored");
    if (grouping)
        notes.push_back(countedText(grouping, "group, object, smoothing or material record",
                               "group, object, smoothing and material records") +
                        " ignored (o, g, s, usemtl, mtllib)");
    if (attributes)
        notes.push_back(countedText(attributes, "texture or normal record", "texture and normal records") +
                        " ignored (vt, vn, vp)");
    if (cornerIndices)
        notes.push_back("texture and normal indices of " + countedText(cornerIndices, "face corner", "face corners") +
                        " ignored");
    if (relative)
        notes.push_back(countedText(relative, "negative (relative) vertex index", "negative (relative) vertex indices") +
                        " resolved");
    if (polylines)
        notes.push_back(countedText(polylines, "polyline or point record", "polyline and point records") +
                        " ignored (l, p)");
    if (unknown)
        notes.push_back(countedText(unknown, "record of an unknown kind", "records of unknown kinds") +
                        " ignored (first at " + firstUnknown + ")");
    return {};
}

/// PLY: the header is text in every PLY file, the body only in ASCII ones.
void sanitisePly(std::string& bytes, std::vector<std::string>& notes) {
    const std::size_t endHeader = bytes.find("end_header");
    if (endHeader == std::string::npos) return sanitiseText(bytes, notes);
    const std::size_t format = bytes.find("format ");
    const bool ascii = format != std::string::npos && format < endHeader &&
                       bytes.compare(format, 12, "format ascii") == 0;
    if (ascii) return sanitiseText(bytes, notes);
    std::size_t bodyStart = bytes.find('\n', endHeader);
    bodyStart = bodyStart == std::string::npos ? bytes.size() : bodyStart + 1;
    std::string header = bytes.substr(0, bodyStart);
    // A CR LF header of a binary file: the body begins after the LF, so nothing of it is lost.
    sanitiseText(header, notes);
    bytes = header + bytes.substr(bodyStart);
}

/// STL: binary when the size is exactly what the count at byte 80 declares (a binary header may
/// well begin with "solid"), else ASCII when it begins with "solid".
bool isBinaryStl(const std::string& bytes) {
    if (bytes.size() >= 84) {
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (84ull + 50ull * count == bytes.size()) return true;
    }
    std::size_t start = bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (start < bytes.size() && std::isspace((unsigned char)bytes[start])) ++start;
    return bytes.compare(start, 5, "solid") != 0;
}

std::string readOm(const std::string& bytes, PolygonSoup& soup) {
    OpenMesh::PolyMesh_ArrayKernelT<> om;
    OpenMesh::IO::Options options = OpenMesh::IO::Options::Binary;
    std::istringstream in(bytes, std::ios::binary);
    bool ok = false;
    // OpenMesh writes its complaints to std::cerr; the caller's message is the one that counts.
    std::ostringstream discard;
    std::streambuf* const oldErr = std::cerr.rdbuf(discard.rdbuf());
    std::streambuf* const oldLog = std::clog.rdbuf(discard.rdbuf());
    try {
        ok = OpenMesh::IO::read_mesh(om, in, ".om", options);
    } catch (const std::exception&) {
        ok = false;
    }
    omerr().flush();
    std::cerr.rdbuf(oldErr);
    std::clog.rdbuf(oldLog);
    if (!ok) return "is not a readable OpenMesh .om file";
    soup.points.reserve(om.n_vertices());
    for (auto vh : om.vertices()) {
        const auto& p = om.point(vh);
        soup.points.emplace_back(p[0], p[1], p[2]);
    }
    // The halfedges came from the file (checked in range by the probe, not for consistency), so
    // each face's loop is walked with a bound instead of OpenMesh's circulator.
    const int halfedges = int(om.n_halfedges()), verticesMade = int(om.n_vertices());
    for (auto fh : om.faces()) {
        std::vector<std::uint32_t> polygon;
        const auto first = om.halfedge_handle(fh);
        auto h = first;
        do {
            if (!h.is_valid() || h.idx() >= halfedges || int(polygon.size()) >= halfedges)
                return "is corrupt: an .om face's halfedges do not form a loop";
            const int v = om.to_vertex_handle(h).idx();
            if (v < 0 || v >= verticesMade) return "is corrupt: an .om face refers to a vertex that does not exist";
            polygon.push_back(std::uint32_t(v));
            h = om.next_halfedge_handle(h);
        } while (h != first);
        soup.polygons.push_back(std::move(polygon));
    }
    return {};
}

template <typename Reader>
std::string readWithCgal(const std::string& bytes, const std::string& ext, PolygonSoup& soup, Reader read) {
    std::vector<Point> points;
    CgalPolygons polygons;
    std::istringstream in(bytes, std::ios::binary);
    bool ok = false;
    try {
        ok = read(in, points, polygons);
    } catch (const std::exception&) {
        ok = false;
    }
    if (!ok) return "is not a readable " + ext + " file (a malformed record)";
    if (points.size() > kMaxMeshVertices)
        return "has " + std::to_string(points.size()) + " vertices, more than the " + std::to_string(kMaxMeshVertices) +
               " a mesh may have";
    if (polygons.size() > kMaxMeshFaces)
        return "has " + std::to_string(polygons.size()) + " faces, more than the " + std::to_string(kMaxMeshFaces) +
               " a mesh may have";
    soup.points.reserve(points.size());
    for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
    soup.polygons.reserve(polygons.size());
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        std::vector<std::uint32_t> polygon;
        polygon.reserve(polygons[f].size());
        for (std::size_t v : polygons[f]) {
            if (v >= points.size())
                return "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", but the file has " +
                       std::to_string(points.size());
            polygon.push_back(std::uint32_t(v));
        }
        soup.polygons.push_back(std::move(polygon));
    }
    return {};
}

}  // namespace

std::string readPolygonSoup(const std::string& path, PolygonSoup& soup) {
    std::string error;
    const std::optional<std::string> bytes = readInputFile(path, kMeshFile, error);
    if (!bytes) return error.compare(0, path.size() + 2, path + ": ") == 0 ? error.substr(path.size() + 2) : error;
    return readPolygonSoupBytes(*bytes, lowerExtension(path), soup);
}

std::string readPolygonSoupBytes(const std::string& original, const std::string& ext, PolygonSoup& soup) {
    soup = PolygonSoup{};
    if (original.empty()) return "is empty (0 bytes)";
    std::string bytes = original;
    std::vector<std::string> notes;
    if (ext == "obj" || ext == "off") sanitiseText(bytes, notes);
    else if (ext == "ply") sanitisePly(bytes, notes);
    else if (ext == "stl" && !isBinaryStl(bytes))
        sanitiseText(bytes, notes);
    else if (ext == "stl") {
        // CGAL takes a file that begins with "solid" for ASCII and falls back to binary only after
        // the ASCII parse appended what it could; the header's 80 bytes are unused in binary STL.
        bytes[0] = 'B';
        std::uint32_t declared = 0;
        if (bytes.size() >= 84) std::memcpy(&declared, bytes.data() + 80, 4);
        const std::uint64_t expected = 84ull + 50ull * declared;
        if (bytes.size() > expected && bytes.size() < expected + 50)
            notes.push_back(countedText(bytes.size() - expected, "byte", "bytes") + " after the last triangle ignored");
    }
    // OBJ's own pre-scan first, for its line numbers; it keeps every line, so the probe's line
    // numbers stay right too.
    if (ext == "obj" && bytes.find('\0') == std::string::npos)
        if (std::string problem = prescanObj(bytes, notes); !problem.empty()) return problem;
    // The structural check of declared counts, truncation and coordinates, on what the reader sees.
    if (std::string problem = probeMeshBytes(bytes, ext); !problem.empty()) return problem;

    std::string problem;
    if (ext == "obj") {
        problem = readWithCgal(bytes, "OBJ", soup, [](std::istream& in, auto& p, auto& f) {
            return CGAL::IO::read_OBJ(in, p, f, CGAL::parameters::verbose(false));
        });
    } else if (ext == "off") {
        problem = readWithCgal(bytes, "OFF", soup, [](std::istream& in, auto& p, auto& f) {
            return CGAL::IO::read_OFF(in, p, f, CGAL::parameters::verbose(false));
        });
    } else if (ext == "ply") {
        problem = readWithCgal(bytes, "PLY", soup, [](std::istream& in, auto& p, auto& f) {
            return CGAL::IO::read_PLY(in, p, f, CGAL::parameters::verbose(false));
        });
    } else if (ext == "stl") {
        problem = readWithCgal(bytes, "STL", soup, [](std::istream& in, auto& p, auto& f) {
            return CGAL::IO::read_STL(in, p, f, CGAL::parameters::verbose(false));
        });
    } else if (ext == "om") {
        problem = readOm(bytes, soup);
    }
    if (problem.empty() && soup.points.empty()) problem = "has no vertices";
    else if (problem.empty() && soup.polygons.empty()) problem = "has no faces";
    if (!problem.empty()) {
        soup = PolygonSoup{};
        return problem;
    }
    soup.notes = std::move(notes);
    return {};
}

namespace {

/// Twice the signed area of the triangle (a, b, c) in the plane.
double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Ear clipping of one simple polygon projected into its best-fit plane; false when no ear is left
/// (a self-intersecting or degenerate polygon), with the triangles found so far in `out`.
bool earClip(const std::vector<glm::dvec2>& corners, const std::vector<std::uint32_t>& ids, double eps,
             std::vector<std::array<std::uint32_t, 3>>& out, std::vector<std::size_t>& left, std::size_t& tests) {
    left.resize(corners.size());
    for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
    // Walk round the polygon; after a clip, look again at the corner before it (its ear changed).
    std::size_t k = 0, misses = 0;
    while (left.size() > 3) {
        if (misses == left.size()) return false;
        const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
        bool ear = cross2(corners[a], corners[b], corners[c]) > eps;  // convex, not straight
        if (ear) {
            tests += left.size();
            for (std::size_t j : left) {
                const glm::dvec2& p = corners[j];
                if (j == a || j == b || j == c || p == corners[a] || p == corners[b] || p == corners[c]) continue;
                if (cross2(corners[a], corners[b], p) >= -eps && cross2(corners[b], corners[c], p) >= -eps &&
                    cross2(corners[c], corners[a], p) >= -eps) {
                    ear = false;
                    break;
                }
            }
        }
        if (!ear) {
            ++misses;
            k = (k + 1) % left.size();
            continue;
        }
        out.push_back({ids[a], ids[b], ids[c]});
        left.erase(left.begin() + std::ptrdiff_t(k));
        k = (k + left.size() - 1) % left.size();
        misses = 0;
    }
    out.push_back({ids[left[0]], ids[left[1]], ids[left[2]]});
    return true;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulatePolygons(const PolygonSoup& soup,
                                                              std::vector<std::string>& notes) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    triangles.reserve(soup.polygons.size());
    std::size_t quads = 0, larger = 0, dropped = 0, fannedLarge = 0, noEar = 0, earTests = 0;
    std::vector<glm::dvec2> corners;
    std::vector<std::size_t> left;
    for (const auto& polygon : soup.polygons) {
        const std::size_t n = polygon.size();
        if (n < 3) {
            ++dropped;
            continue;
        }
        if (n == 3) {
            triangles.push_back({polygon[0], polygon[1], polygon[2]});
            continue;
        }
        ++(n == 4 ? quads : larger);
        auto fan = [&](const std::vector<std::uint32_t>& ids) {
            for (std::size_t i = 1; i + 1 < ids.size(); ++i) triangles.push_back({ids[0], ids[i], ids[i + 1]});
        };
        const bool indicesValid = std::all_of(polygon.begin(), polygon.end(),
                                              [&](std::uint32_t v) { return v < soup.points.size(); });
        if (!indicesValid) {  // left for findMeshFaults to name
            fan(polygon);
            continue;
        }
        // Newell's normal: the best-fit plane's normal, pointing the way the polygon winds.
        glm::dvec3 normal(0.0), lo(INFINITY), hi(-INFINITY);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec3& p = soup.points[polygon[i]];
            const glm::dvec3& q = soup.points[polygon[(i + 1) % n]];
            normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const double length = glm::length(normal);
        if (!(length > 0.0) || !std::isfinite(length)) {  // degenerate: named by findMeshFaults
            fan(polygon);
            continue;
        }
        normal /= length;
        const glm::dvec3 helper = std::fabs(normal.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 u = glm::normalize(glm::cross(helper, normal));
        const glm::dvec3 v = glm::cross(normal, u);
        corners.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec3 p = soup.points[polygon[i]] - lo;
            corners[i] = {glm::dot(p, u), glm::dot(p, v)};
        }
        const double extent = glm::length(hi - lo);
        const double eps = 1e-12 * extent * extent;
        bool convex = true;
        for (std::size_t i = 0; i < n && convex; ++i)
            convex = cross2(corners[i], corners[(i + 1) % n], corners[(i + 2) % n]) > eps;
        if (convex) {
            fan(polygon);
        } else if (n > kMaxEarClipCorners || earTests > kEarTestBudget) {
            ++fannedLarge;
            fan(polygon);
        } else {
            if (!earClip(corners, polygon, eps, triangles, left, earTests)) {
                // No ear: self-intersecting or with straight corners only; the rest is fanned, and
                // whatever that overlaps is named by findMeshFaults.
                ++noEar;
                std::vector<std::uint32_t> rest;
                for (std::size_t i : left) rest.push_back(polygon[i]);
                fan(rest);
            }
        }
    }
    if (quads || larger) {
        std::string text;
        if (quads) text = countedText(quads, "quad", "quads");
        if (quads && larger) text += " and ";
        if (larger) text += countedText(larger, "polygon", "polygons") + " of more than 4 corners";
        notes.push_back(text + " triangulated");
    }
    if (fannedLarge)
        notes.push_back(countedText(fannedLarge, "concave polygon", "concave polygons") + " of more than " +
                        std::to_string(kMaxEarClipCorners) +
                        " corners (or beyond the file's budget of ear tests) split as a fan (it may overlap itself)");
    if (noEar) notes.push_back(countedText(noEar, "polygon", "polygons") + " that cross themselves split as a fan");
    if (dropped) notes.push_back(countedText(dropped, "polygon", "polygons") + " of fewer than 3 corners dropped");
    return triangles;
}

}  // namespace palpate
