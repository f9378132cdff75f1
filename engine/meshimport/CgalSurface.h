#pragma once
// CGAL's surface mesh as repair and remeshing use it, and the conversions to and from the plain
// TriangleSurface they hand on (docs/meshes.md, "Repair"). Included by those two files only, so
// that CGAL's headers stay out of the module's public ones.

#include "engine/meshimport/TriangleSurface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <map>

namespace palpate {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

/// The mesh's vertices in its order and its triangles (faces of more corners keep their first three).
inline TriangleSurface toTriangleSurface(const CgalMesh& mesh) {
    TriangleSurface s;
    std::map<CgalMesh::Vertex_index, std::uint32_t> index;
    s.positionsMm.reserve(mesh.number_of_vertices());
    for (CgalMesh::Vertex_index v : mesh.vertices()) {
        index[v] = std::uint32_t(s.positionsMm.size());
        const auto& p = mesh.point(v);
        s.positionsMm.emplace_back(p.x(), p.y(), p.z());
    }
    s.triangles.reserve(mesh.number_of_faces());
    for (CgalMesh::Face_index f : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        int k = 0;
        for (CgalMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            if (k < 3) t[k++] = index[v];
        if (k == 3) s.triangles.push_back(t);
    }
    return s;
}

/// False when a triangle cannot be added (the surface is not a manifold mesh).
inline bool toCgalMesh(const TriangleSurface& surface, CgalMesh& mesh) {
    std::vector<CgalMesh::Vertex_index> handles;
    handles.reserve(surface.positionsMm.size());
    for (const glm::dvec3& p : surface.positionsMm) handles.push_back(mesh.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z)));
    for (const auto& t : surface.triangles)
        if (mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]) == CgalMesh::null_face()) return false;
    return true;
}

}  // namespace palpate
