#include "engine/lod/MeshDecimation.h"

#include <algorithm>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>

#include <cmath>
#include <sstream>

namespace palpate {

namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;
using Decimater = OpenMesh::Decimater::DecimaterT<OmMesh>;

/// Reports progress and passes the cancel flag to the Decimater, which stops at a consistent state.
class ProgressObserver : public OpenMesh::Decimater::Observer {
public:
    ProgressObserver(std::size_t interval, std::size_t plannedCollapses, const std::function<void(double)>& progress,
                     const std::atomic<bool>* cancel)
        : Observer(interval), mPlanned(plannedCollapses), mProgress(progress), mCancel(cancel) {}
    void notify(std::size_t step) override {
        if (mProgress && mPlanned > 0) mProgress(std::min(1.0, double(mDoneBefore + step) / double(mPlanned)));
    }
    bool abort() const override { return mCancel && mCancel->load(std::memory_order_relaxed); }
    void finishedCall(std::size_t collapses) { mDoneBefore += collapses; }

private:
    std::size_t mPlanned;
    std::size_t mDoneBefore = 0;
    const std::function<void(double)>& mProgress;
    const std::atomic<bool>* mCancel;
};

DecimatedSurface snapshot(const OmMesh& om, std::size_t target) {
    DecimatedSurface s;
    s.targetVertices = target;
    std::vector<VertexId> compact(om.n_vertices(), kNoVertex);
    for (auto vh : om.vertices()) {  // skips deleted vertices
        compact[vh.idx()] = VertexId(s.positionsMm.size());
        const auto& p = om.point(vh);
        s.positionsMm.emplace_back(p[0], p[1], p[2]);
    }
    for (auto fh : om.faces()) {
        std::array<VertexId, 3> t{};
        int i = 0;
        for (auto vh : om.fv_range(fh))
            if (i < 3) t[i++] = compact[vh.idx()];
        s.triangles.push_back(t);
    }
    return s;
}

}  // namespace

Problems validateDecimationGuards(const DecimationGuards& g) {
    if (!std::isfinite(g.maxNormalDeviationDeg) || g.maxNormalDeviationDeg <= 0.0 || g.maxNormalDeviationDeg > 180.0)
        return oneProblem("maxNormalDeviationDeg", "max normal deviation must be in (0, 180] degrees");
    if (!std::isfinite(g.maxAspectRatio) || g.maxAspectRatio < 1.0)
        return oneProblem("maxAspectRatio", "max aspect ratio must be at least 1");
    return {};
}

DecimationResult decimateProgressively(const TissueMesh& source, std::span<const std::size_t> targets,
                                       const DecimationGuards& guards, const std::function<void(double)>& progress,
                                       const std::atomic<bool>* cancel) {
    DecimationResult result;
    if (const std::string e = joinedMessages(validateDecimationGuards(guards)); !e.empty()) {
        result.error = e;
        return result;
    }
    {
        std::vector<std::size_t> valence(source.vertexCount(), 0);
        for (const auto& t : source.triangles())
            for (const VertexId v : t) ++valence[v];
        const auto widest = std::max_element(valence.begin(), valence.end());
        if (widest != valence.end() && *widest > kMaxDecimationValence) {
            result.error = source.report().source + ": vertex " +
                           std::to_string(source.originalIndex()[std::size_t(widest - valence.begin())]) + " has " +
                           std::to_string(*widest) + " triangles around it (at most " +
                           std::to_string(kMaxDecimationValence) +
                           " for levels of detail: a fan that wide makes decimation take hours); remesh the mesh "
                           "first (palpate-cli mesh import --remesh-edge-mm E, or the window's mesh import)";
            return result;
        }
    }
    OmMesh om;
    om.request_vertex_status();
    om.request_edge_status();
    om.request_face_status();
    om.request_face_normals();  // ModNormalFlippingT compares normals before and after a collapse
    std::vector<OmMesh::VertexHandle> handles;
    handles.reserve(source.vertexCount());
    for (const glm::vec3& p : source.restPositionsMm()) handles.push_back(om.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
    std::size_t rejected = 0;
    for (const auto& t : source.triangles())
        if (!om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid()) ++rejected;
    if (rejected > 0) {
        result.error = source.report().source + ": " + std::to_string(rejected) +
                       " triangles could not be added to OpenMesh (non-manifold or inconsistently oriented)";
        return result;
    }
    om.update_face_normals();

    Decimater decimater(om);
    OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric;
    OpenMesh::Decimater::ModNormalFlippingT<OmMesh>::Handle flipping;
    OpenMesh::Decimater::ModAspectRatioT<OmMesh>::Handle aspect;
    decimater.add(quadric);
    decimater.add(flipping);
    decimater.add(aspect);
    decimater.module(quadric).unset_max_err();  // the quadric ranks; the vertex count stops
    decimater.module(flipping).set_max_normal_deviation(guards.maxNormalDeviationDeg);
    decimater.module(aspect).set_aspect_ratio(float(guards.maxAspectRatio));
    if (!decimater.initialize()) {
        result.error = "the OpenMesh decimater did not initialise (no priority module)";
        return result;
    }

    const std::size_t lowest = targets.empty() ? source.vertexCount() : targets.back();
    const std::size_t planned = source.vertexCount() > lowest ? source.vertexCount() - lowest : 0;
    ProgressObserver observer(std::max<std::size_t>(1, planned / 200), planned, progress, cancel);
    decimater.set_observer(&observer);
    std::size_t current = source.vertexCount();
    for (std::size_t target : targets) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            result.cancelled = true;
            break;
        }
        if (target < current) {
            // decimate(), not decimate_to(): n_vertices() still counts the collapsed (deleted but not
            // yet collected) vertices of the earlier levels.
            const std::size_t collapses = decimater.decimate(current - target);
            observer.finishedCall(collapses);
            current -= collapses;
        }
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            result.cancelled = true;  // stopped inside this level: it is not complete
            break;
        }
        result.surfaces.push_back(snapshot(om, target));
    }
    decimater.set_observer(nullptr);
    if (progress && !result.cancelled) progress(1.0);
    return result;
}

}  // namespace palpate
