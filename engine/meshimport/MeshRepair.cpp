#include "engine/meshimport/MeshRepair.h"

#include "engine/core/CountedText.h"
#include "engine/meshimport/CgalSurface.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <exception>
#include <iterator>
#include <string>

namespace palpate {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = CgalKernel::Point_3;
using Mesh = CgalMesh;

/// A polygon's corners as a canonical key: the rotation starting at its smallest index.
std::vector<std::size_t> rotatedToSmallest(const std::vector<std::size_t>& polygon) {
    std::vector<std::size_t> p = polygon;
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    return p;
}

/// Polygons whose corners are the same cycle run the other way (what orient_polygon_soup did).
std::size_t reversedPolygons(const std::vector<std::vector<std::size_t>>& before,
                             const std::vector<std::vector<std::size_t>>& after) {
    if (before.size() != after.size()) return 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (before[i] == after[i] || before[i].size() != after[i].size()) continue;
        std::vector<std::size_t> reversed(before[i].rbegin(), before[i].rend());
        if (rotatedToSmallest(reversed) == rotatedToSmallest(after[i])) ++n;
    }
    return n;
}

}  // namespace

MeshRepairOutcome repairPolygonSoup(PolygonSoup soup, const MeshRepairDef& def, const std::function<bool()>& cancelled) {
    MeshRepairOutcome out;
    auto stop = [&] { return cancelled && cancelled(); };
    auto cancel = [&] {
        out.error = "cancelled";
        out.surface.reset();
        return out;
    };
    try {
        std::vector<Point> points;
        points.reserve(soup.points.size());
        for (const glm::dvec3& p : soup.points) points.emplace_back(p.x, p.y, p.z);
        std::vector<std::vector<std::size_t>> polygons;
        polygons.reserve(soup.polygons.size());
        for (const auto& polygon : soup.polygons) polygons.emplace_back(polygon.begin(), polygon.end());
        soup = {};

        // 1. The soup: duplicate points merged, then degenerate, duplicate and invalid polygons and
        //    unused points removed.
        if (const std::size_t merged = PMP::merge_duplicate_points_in_polygon_soup(points, polygons))
            out.changes.push_back("merged " + countedText(merged, "duplicate vertex", "duplicate vertices"));
        const std::size_t pointsBefore = points.size(), polygonsBefore = polygons.size();
        PMP::repair_polygon_soup(points, polygons);
        if (polygons.size() < polygonsBefore)
            out.changes.push_back("removed " +
                                  countedText(polygonsBefore - polygons.size(), "degenerate or duplicate face",
                                        "degenerate or duplicate faces"));
        if (points.size() < pointsBefore)
            out.changes.push_back("removed " + countedText(pointsBefore - points.size(), "unused vertex", "unused vertices"));
        if (polygons.empty()) {
            out.error = "no faces are left after removing the degenerate ones";
            return out;
        }
        if (stop()) return cancel();

        // 2. Orientation made consistent; points where the surface is not manifold are split so
        //    that it can be.
        const std::size_t pointsBeforeOrient = points.size();
        const auto polygonsBeforeOrient = polygons;
        PMP::orient_polygon_soup(points, polygons);
        std::size_t flipped = reversedPolygons(polygonsBeforeOrient, polygons);
        // CGAL keeps one face of each piece as it was; when that face was one of the few wrong
        // ones, the many right ones were reversed. Undo that, so that the report counts the
        // minority (outward normals are settled at the end).
        if (points.size() == pointsBeforeOrient && 2 * flipped > polygons.size()) {
            for (auto& polygon : polygons) std::reverse(polygon.begin(), polygon.end());
            flipped = polygons.size() - flipped;
        }
        if (flipped)
            out.changes.push_back("reversed " + countedText(flipped, "face", "faces") + " to make the orientation consistent");
        if (points.size() > pointsBeforeOrient)
            out.changes.push_back("split " + countedText(points.size() - pointsBeforeOrient, "non-manifold vertex", "non-manifold vertices") +
                                  " (copies made so that each fan of faces is its own)");
        if (stop()) return cancel();

        Mesh mesh;
        PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
        points.clear();
        polygons.clear();
        if (!CGAL::is_triangle_mesh(mesh)) {
            const std::size_t before = mesh.number_of_faces();
            PMP::triangulate_faces(mesh);
            out.changes.push_back("triangulated polygons: " + std::to_string(before) + " faces became " +
                                  std::to_string(mesh.number_of_faces()) + " triangles");
        }

        // 3. Borders that run along each other (a seam left by a splitting exporter) are stitched.
        if (const std::size_t stitched = PMP::stitch_borders(mesh))
            out.changes.push_back("stitched " + countedText(stitched, "pair of border edges", "pairs of border edges") +
                                  " that ran along each other");
        if (const std::size_t split = PMP::duplicate_non_manifold_vertices(mesh))
            out.changes.push_back("split " + countedText(split, "non-manifold vertex", "non-manifold vertices"));
        {
            const std::size_t before = mesh.number_of_faces();
            PMP::remove_degenerate_faces(mesh);
            mesh.collect_garbage();
            if (mesh.number_of_faces() < before)
                out.changes.push_back("removed " + countedText(before - mesh.number_of_faces(), "degenerate triangle", "degenerate triangles"));
        }
        if (stop()) return cancel();

        // 4. Pieces: the largest kept unless all are asked for.
        {
            auto componentMap = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
            const std::size_t components = PMP::connected_components(mesh, componentMap);
            mesh.remove_property_map(componentMap);
            if (components > 1 && def.keep == KeepComponents::Largest) {
                const std::size_t facesBefore = mesh.number_of_faces();
                const std::size_t removed = PMP::keep_largest_connected_components(mesh, 1);
                mesh.collect_garbage();
                out.changes.push_back("kept the largest of " + std::to_string(components) + " components (removed " +
                                      countedText(removed, "component", "components") + ", " +
                                      countedText(facesBefore - mesh.number_of_faces(), "triangle", "triangles") + ")");
            } else if (components > 1) {
                out.changes.push_back("kept all " + std::to_string(components) + " components");
            }
        }
        if (stop()) return cancel();

        // 5. Holes closed with refined, faired patches.
        if (def.fillHoles) {
            std::vector<Mesh::Halfedge_index> borders;
            PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
            for (Mesh::Halfedge_index h : borders) {
                if (stop()) return cancel();
                const std::size_t edges = std::size_t(std::distance(CGAL::halfedges_around_face(h, mesh).begin(),
                                                                      CGAL::halfedges_around_face(h, mesh).end()));
                std::vector<Mesh::Face_index> faces;
                std::vector<Mesh::Vertex_index> vertices;
                const bool faired = std::get<0>(PMP::triangulate_refine_and_fair_hole(
                    mesh, h, std::back_inserter(faces), std::back_inserter(vertices)));
                if (faces.empty()) {
                    out.changes.push_back("could not fill a hole of " + countedText(edges, "edge", "edges"));
                    continue;
                }
                out.changes.push_back("filled a hole of " + countedText(edges, "edge", "edges") + " with " +
                                      countedText(faces.size(), "triangle", "triangles") +
                                      (faired ? "" : " (not faired: the patch is flat)"));
            }
        }

        // 6. Outward normals on a closed surface.
        if (CGAL::is_closed(mesh) && !PMP::is_outward_oriented(mesh)) {
            PMP::reverse_face_orientations(mesh);
            out.changes.push_back("reversed all faces so that the normals point outward");
        }
        mesh.collect_garbage();
        if (mesh.number_of_faces() == 0) {
            out.error = "no faces are left after repair";
            return out;
        }
        out.surface = toTriangleSurface(mesh);
    } catch (const std::exception& e) {
        out.error = std::string("repair failed: ") + e.what();
        out.surface.reset();
    }
    return out;
}

}  // namespace palpate
