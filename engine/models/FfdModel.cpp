#include "engine/models/FfdModel.h"

#include "engine/models/FlushDenormals.h"
#include "engine/models/OctreeQueries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {

FfdLattice makeLattice(const TissueMesh& mesh, const FfdParams& params) {
    const auto errors = validateFfdParams(params);
    if (!errors.empty()) {
        std::string text = "invalid FFD parameters:";
        for (const auto& e : errors) text += "\n  " + e.message;
        throw std::invalid_argument(text);
    }
    const glm::dvec3 lo(mesh.boundsMinMm()), hi(mesh.boundsMaxMm());
    const double margin = params.marginFraction * std::max(glm::length(hi - lo), 1e-3);
    return FfdLattice(lo - glm::dvec3(margin), hi + glm::dvec3(margin), params.controlPointsPerAxis);
}

}  // namespace

FfdModel::FfdModel(const TissueMesh& mesh, const Octree& octree, const FfdParams& params)
    : mMesh(mesh), mOctree(octree), mParams(params), mLattice(makeLattice(mesh, params)) {
    mPoints = params.controlPointsPerAxis;
    mMoved = params.movedPerAxis;
    const std::size_t n = mesh.vertexCount();
    const int degree = mLattice.degree();
    mBasis.resize(n * 3 * std::size_t(mPoints));
    double b[kMaxFfdPointsPerAxis];
    for (std::size_t v = 0; v < n; ++v) {
        const glm::dvec3 stu = mLattice.latticeCoordinates(glm::dvec3(mesh.restPositionsMm()[v]));
        for (int axis = 0; axis < 3; ++axis) {
            FfdLattice::bernstein(degree, stu[axis], b);
            for (int i = 0; i < mPoints; ++i) mBasis[(v * 3 + std::size_t(axis)) * std::size_t(mPoints) + std::size_t(i)] = float(b[i]);
        }
    }
    mShape.assign(n, 0.0f);
    mPositions = mesh.restPositionsMm();
}

glm::dvec3 FfdModel::latticeCoordinatesOf(VertexId v) const {
    return mLattice.latticeCoordinates(glm::dvec3(mMesh.restPositionsMm()[v]));
}

void FfdModel::reset() {
    std::copy(mMesh.restPositionsMm().begin(), mMesh.restPositionsMm().end(), mPositions.begin());
    mActive = false;
    mCentre = kNoVertex;
    mDisplacementMm = glm::vec3(0.0f);
    mTouched = kNoVertex;
    mContact = false;
    mMaxDisplacementMm = 0.0f;
}

void FfdModel::shapeFor(VertexId t) {
    // The moved block: per axis, the movedPerAxis control points whose index is nearest s * degree
    // (where the touched vertex's Bernstein weights peak). With w_abc = B_a(s) B_b(t) B_c(u) the
    // touched vertex's weights on the block, the least-norm control displacements that move it by
    // D are dP_abc = w_abc D / sum(w^2) (the pseudo-inverse of the 1 x block map); every vertex then
    // moves by sum_abc B_abc(v) dP_abc = s_v D, and both sums factor per axis.
    const glm::dvec3 stu = latticeCoordinatesOf(t);
    const int degree = mLattice.degree();
    double sumW2 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const int start = int(std::lround(stu[axis] * degree - 0.5 * (mMoved - 1)));
        mBlockStart[axis] = std::clamp(start, 0, mPoints - mMoved);
        const float* bt = &mBasis[(std::size_t(t) * 3 + std::size_t(axis)) * std::size_t(mPoints)];
        double axisW2 = 0.0;
        for (int a = mBlockStart[axis]; a < mBlockStart[axis] + mMoved; ++a) axisW2 += double(bt[a]) * bt[a];
        sumW2 *= axisW2;
    }
    mBlockScale = sumW2 > 0.0 ? 1.0 / sumW2 : 0.0;
    const std::size_t n = mMesh.vertexCount();
    const std::size_t stride = std::size_t(mPoints);
    const float* basisT = &mBasis[std::size_t(t) * 3 * stride];
    float maxAbs = 0.0f;
    for (std::size_t v = 0; v < n; ++v) {
        const float* bv = &mBasis[v * 3 * stride];
        double s = mBlockScale;
        for (int axis = 0; axis < 3; ++axis) {
            const float* x = bv + std::size_t(axis) * stride;
            const float* y = basisT + std::size_t(axis) * stride;
            float dot = 0.0f;
            for (int a = mBlockStart[axis]; a < mBlockStart[axis] + mMoved; ++a) dot += x[a] * y[a];
            s *= dot;
        }
        mShape[v] = float(s);
        maxAbs = std::max(maxAbs, std::fabs(float(s)));
    }
    mShape[t] = 1.0f;  // exactly: the touched vertex follows the tool (1 up to rounding anyway)
    mMaxAbsShape = std::max(maxAbs, 1.0f);
    mCentre = t;
}

void FfdModel::release() {
    if (mActive) std::copy(mMesh.restPositionsMm().begin(), mMesh.restPositionsMm().end(), mPositions.begin());
    mActive = false;
    mDisplacementMm = glm::vec3(0.0f);
    mMaxDisplacementMm = 0.0f;
}

TickResult FfdModel::step(const glm::vec3& tool, double /*dtS*/) {
    const FlushDenormals flush;  // Bernstein tails far from the contact are subnormal (FlushDenormals.h)
    const bool toolValid = std::isfinite(tool.x) && std::isfinite(tool.y) && std::isfinite(tool.z);
    const auto& rest = mMesh.restPositionsMm();
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = nearestWithBoundedDisplacement(mOctree, tool, mPositions, mMaxDisplacementMm, mTouched);
        if (found != kNoVertex) touched = found;
    }
    TickResult result;
    result.touched = touched;
    float depth = 0.0f;
    glm::vec3 n(0.0f);
    if (toolValid && touched != kNoVertex) {
        n = mMesh.restNormals()[touched];
        depth = glm::dot(rest[touched] - tool, n);
        result.penetrationMm = glm::dot(mPositions[touched] - tool, n);
    }
    const bool contact = toolValid && touched != kNoVertex && depth > 0.0f;
    if (contact) {
        if (touched != mCentre) shapeFor(touched);
        // The surface point under the tool follows it along its rest normal: D = -d n.
        mDisplacementMm = -depth * n;
        const std::size_t count = mMesh.vertexCount();
        const float* shape = mShape.data();
        const glm::vec3 d = mDisplacementMm;
        for (std::size_t v = 0; v < count; ++v) mPositions[v] = rest[v] + shape[v] * d;
        mActive = true;
        mMaxDisplacementMm = depth * mMaxAbsShape;
        result.forceN = (float(mParams.stiffnessNPerMm) * depth) * n;  // k_s times the touched vertex's displacement
    } else if (mActive) {
        release();
    }
    mTouched = touched;
    mContact = contact;
    result.contact = contact;
    return result;
}

std::vector<glm::dvec3> FfdModel::controlPointDisplacementsMm() const {
    std::vector<glm::dvec3> dP(mLattice.controlPointCount(), glm::dvec3(0.0));
    if (!mActive || mCentre == kNoVertex) return dP;
    const std::size_t stride = std::size_t(mPoints);
    const float* bt = &mBasis[std::size_t(mCentre) * 3 * stride];
    for (int a = mBlockStart[0]; a < mBlockStart[0] + mMoved; ++a)
        for (int b = mBlockStart[1]; b < mBlockStart[1] + mMoved; ++b)
            for (int c = mBlockStart[2]; c < mBlockStart[2] + mMoved; ++c) {
                const double w = double(bt[a]) * bt[stride + std::size_t(b)] * bt[2 * stride + std::size_t(c)];
                dP[mLattice.index(a, b, c)] = (w * mBlockScale) * glm::dvec3(mDisplacementMm);
            }
    return dP;
}

std::size_t FfdModel::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                    std::size_t capacity) const {
    if (!mActive) return 0;
    const auto& rest = mMesh.restPositionsMm();
    std::size_t count = 0;
    for (VertexId v = 0; v < mPositions.size(); ++v) {
        if (mPositions[v] == rest[v]) continue;
        if (count < capacity) {
            ids[count] = v;
            positionsMm[count] = mPositions[v];
            rings[count] = v == mCentre ? 0 : 1;  // no rings here: 0 the touched vertex, 1 the rest of the dent
        }
        ++count;
    }
    return count;
}

}  // namespace palpate
