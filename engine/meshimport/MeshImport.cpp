#include "engine/meshimport/MeshImport.h"

#include "engine/core/PolygonSoup.h"
#include "engine/meshimport/MeshRemesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace palpate {

namespace {

std::string fixed(double value, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << value;
    return s.str();
}

std::optional<TissueMesh> buildMesh(const TriangleSurface& surface, const std::string& source,
                                    std::vector<std::string>* errors, std::vector<std::string>* warnings) {
    std::vector<glm::vec3> positions(surface.positionsMm.begin(), surface.positionsMm.end());
    auto loaded = TissueMesh::fromTriangles(std::move(positions), surface.triangles, source);
    if (errors) errors->insert(errors->end(), loaded.report.errors.begin(), loaded.report.errors.end());
    if (warnings) warnings->insert(warnings->end(), loaded.report.warnings.begin(), loaded.report.warnings.end());
    return std::move(loaded.mesh);
}

void roundnessRow(std::ostringstream& out, const char* label, const RingRoundness& r) {
    out << "    " << label;
    for (int k = 1; k <= r.ringCount; ++k) out << "  ring " << k << " " << fixed(r.ringDistanceCv[k], 3);
    out << "  edges " << fixed(r.edgeLengthCv, 3) << "  (mean edge " << fixed(r.meanEdgeMm, 2) << " mm, "
        << fixed(r.minEdgeMm, 2) << " to " << fixed(r.maxEdgeMm, 2) << ")\n";
}

}  // namespace

double suggestedRemeshEdgeMm(const glm::dvec3& sizeMm) {
    const double diagonal = glm::length(sizeMm);
    return std::max(kMinRemeshEdgeMm, std::round(diagonal / 60.0 * 10.0) / 10.0);
}

MeshImportResult importMesh(const std::string& path, const MeshImportDef& def, const ImportProgress& progress) {
    MeshImportResult r;
    r.source = path;
    r.unit = def.unit;
    auto error = [&](const std::string& problem) { r.errors.push_back(path + ": " + problem); };
    auto report = [&](double fraction, const char* stage) { return !progress || progress(fraction, stage); };
    auto cancelled = [&] {
        error("cancelled");
        r.mesh.reset();
        return r;
    };

    if (def.remeshEdgeMm != 0.0 && !(def.remeshEdgeMm >= kMinRemeshEdgeMm && std::isfinite(def.remeshEdgeMm))) {
        error("remeshing edge length " + fixed(def.remeshEdgeMm, 3) + " mm: use 0 (no remeshing) or at least " +
              fixed(kMinRemeshEdgeMm, 2) + " mm");
        return r;
    }
    if (def.remeshIterations < 1 || def.remeshIterations > kMaxRemeshIterations) {
        error("remeshing iterations " + std::to_string(def.remeshIterations) + ": use 1 to " +
              std::to_string(kMaxRemeshIterations));
        return r;
    }
    if (!report(0.0, "reading")) return cancelled();

    PolygonSoup soup;
    if (const std::string problem = readPolygonSoup(path, soup); !problem.empty()) {
        error(problem);
        return r;
    }
    r.sourceVertices = soup.points.size();
    r.sourcePolygons = soup.polygons.size();
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (glm::dvec3& p : soup.points) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        p *= def.unit.mmPerUnit;
    }
    if (lo.x <= hi.x) {
        r.diagonalInFileUnits = glm::length(hi - lo);
        r.sizeMm = (hi - lo) * def.unit.mmPerUnit;
        r.suggestion = suggestMeshUnit(r.diagonalInFileUnits, def.unit);
    }

    const std::vector<std::array<std::uint32_t, 3>> triangles = triangulatePolygons(soup, soup.notes);
    r.notes = soup.notes;
    r.faults = findMeshFaults(soup.points, triangles);
    TriangleSurface source{soup.points, triangles};
    std::optional<TissueMesh> sourceMesh;
    if (!r.faults.hasErrors()) sourceMesh = buildMesh(source, path, nullptr, nullptr);
    if (!report(0.1, "measuring")) return cancelled();
    if (sourceMesh) r.roundnessBefore = measureRingRoundness(*sourceMesh, def.roundnessRings);

    TriangleSurface surface;
    if (def.repair) {
        if (!report(0.2, "repairing")) return cancelled();
        MeshRepairOutcome repaired = repairPolygonSoup(std::move(soup), MeshRepairDef{def.keep, def.fillHoles},
                                                       [&] { return !report(0.3, "repairing"); });
        r.changes = repaired.changes;
        if (!repaired.surface) {
            error(repaired.error);
            return r;
        }
        surface = std::move(*repaired.surface);
        if (!r.roundnessBefore) {
            if (auto repairedMesh = buildMesh(surface, path, nullptr, nullptr))
                r.roundnessBefore = measureRingRoundness(*repairedMesh, def.roundnessRings);
        }
    } else {
        if (r.faults.hasErrors()) {
            for (const std::string& fault : r.faults.errorTexts()) error(fault);
            error("repair these faults with --repair (Repair in File > Import Mesh...)");
            return r;
        }
        surface = std::move(source);
    }

    if (def.remeshEdgeMm > 0.0) {
        if (!report(0.5, "remeshing")) return cancelled();
        const std::string problem = remeshIsotropic(
            surface, MeshRemeshDef{def.remeshEdgeMm, def.remeshIterations},
            [&](double fraction) { return report(0.5 + 0.4 * fraction, "remeshing"); }, r.changes);
        if (!problem.empty()) {
            error(problem);
            return r;
        }
    }

    if (!report(0.9, "measuring")) return cancelled();
    r.mesh = buildMesh(surface, path, &r.errors, &r.warnings);
    if (!r.mesh) return r;
    if (def.repair || def.remeshEdgeMm > 0.0) r.roundnessAfter = measureRingRoundness(*r.mesh, def.roundnessRings);
    else r.roundnessAfter = r.roundnessBefore;
    report(1.0, "done");
    return r;
}

std::string MeshImportResult::text() const {
    std::ostringstream out;
    out << source << " (read in " << unit.description() << ")\n";
    out << "  read: " << sourceVertices << " vertices, " << sourcePolygons << " faces\n";
    out << "  size: " << fixed(sizeMm.x, 1) << " x " << fixed(sizeMm.y, 1) << " x " << fixed(sizeMm.z, 1)
        << " mm (diagonal " << fixed(glm::length(sizeMm), 1) << " mm)\n";
    if (suggestion)
        out << "  suggested unit: " << suggestion->unit.text() << " (" << suggestion->reason << ")\n";
    for (const std::string& note : notes) out << "  tolerated: " << note << "\n";
    const auto faultErrors = faults.errorTexts(), faultWarnings = faults.warningTexts();
    if (faultErrors.empty() && faultWarnings.empty()) out << "  faults: none\n";
    for (const std::string& f : faultErrors) out << "  fault: " << f << "\n";
    for (const std::string& f : faultWarnings) out << "  found: " << f << "\n";
    for (const std::string& c : changes) out << "  changed: " << c << "\n";
    if (roundnessBefore || roundnessAfter) {
        out << "  ring roundness (coefficient of variation of the distances to ring k; 0 = round):\n";
        if (roundnessBefore) roundnessRow(out, "before:", *roundnessBefore);
        if (roundnessAfter) roundnessRow(out, "after: ", *roundnessAfter);
    }
    if (mesh)
        out << "  result: " << mesh->vertexCount() << " vertices, " << mesh->triangleCount() << " triangles, mean edge "
            << fixed(mesh->meanEdgeLengthMm(), 2) << " mm\n";
    for (const std::string& w : warnings) out << "  warning: " << w << "\n";
    for (const std::string& e : errors) out << "  error: " << e << "\n";
    return out.str();
}

}  // namespace palpate
