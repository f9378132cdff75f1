#include "engine/meshimport/MeshRemesh.h"

#include "base/io/FileLimits.h"
#include "engine/meshimport/CgalSurface.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <exception>
#include <iterator>
#include <sstream>

namespace palpate {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Mesh = CgalMesh;

std::string millimetres(double value) {
    std::ostringstream s;
    s.precision(3);
    s << value << " mm";
    return s.str();
}

}  // namespace

double remeshedTriangleEstimate(double areaMm2, double edgeMm) {
    return edgeMm > 0.0 ? areaMm2 / (std::sqrt(3.0) / 4.0 * edgeMm * edgeMm) : INFINITY;
}

std::string remeshIsotropic(TriangleSurface& surface, const MeshRemeshDef& def,
                            const std::function<bool(double)>& progress, std::vector<std::string>& changes) {
    if (!(def.edgeMm > 0.0) || !std::isfinite(def.edgeMm)) return "the remeshing edge length must be a positive number of mm";
    try {
        Mesh mesh;
        if (!toCgalMesh(surface, mesh)) return "the surface is not a manifold mesh (repair it first)";

        // A target far below the mesh's scale would make millions of triangles: refuse it before
        // CGAL spends minutes and gigabytes on it.
        const double area = PMP::area(mesh);
        const double estimate = remeshedTriangleEstimate(area, def.edgeMm);
        if (estimate > double(kMaxMeshFaces)) {
            std::ostringstream s;
            s << "remeshing at " << millimetres(def.edgeMm) << " would make about " << std::llround(estimate)
              << " triangles (the surface is " << std::llround(area) << " mm^2), more than a mesh may have ("
              << kMaxMeshFaces << "); choose a longer edge";
            return s.str();
        }
        const std::size_t verticesBefore = mesh.number_of_vertices(), facesBefore = mesh.number_of_faces();

        // Borders stay where they are: split to the target length first, then protected
        // (as CGAL's own example for open meshes does).
        std::vector<Mesh::Edge_index> border;
        PMP::border_halfedges(faces(mesh), mesh, boost::make_function_output_iterator([&](Mesh::Halfedge_index h) {
                                  border.push_back(mesh.edge(h));
                              }));
        if (!border.empty()) PMP::split_long_edges(border, def.edgeMm, mesh);
        const int iterations = std::max(1, def.iterations);
        for (int i = 0; i < iterations; ++i) {
            PMP::isotropic_remeshing(faces(mesh), def.edgeMm, mesh,
                                     PMP::parameters::number_of_iterations(1).protect_constraints(!border.empty()));
            if (progress && !progress(double(i + 1) / double(iterations))) return "cancelled";
        }
        mesh.collect_garbage();

        TriangleSurface out = toTriangleSurface(mesh);
        changes.push_back("remeshed to " + millimetres(def.edgeMm) + " edges (" + std::to_string(iterations) +
                          " iterations): " + std::to_string(verticesBefore) + " vertices and " + std::to_string(facesBefore) +
                          " triangles became " + std::to_string(out.positionsMm.size()) + " and " +
                          std::to_string(out.triangles.size()));
        surface = std::move(out);
        return {};
    } catch (const std::exception& e) {
        return std::string("remeshing failed: ") + e.what();
    }
}

}  // namespace palpate
