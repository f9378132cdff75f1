#include "engine/models/MassSpringModel.h"

#include "engine/models/FlushDenormals.h"
#include "engine/models/OctreeQueries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {
constexpr std::uint32_t kNoSlot = 0xffffffffu;
constexpr std::uint8_t kNotInRing = 0xff;
// Stability bounds of the explicit integrators on an undamped oscillator, h * omega < bound, and
// the margin the automatic sub-step count keeps from them.
constexpr double kSymplecticBound = 2.0;
constexpr double kRk4Bound = 2.78;
constexpr double kStabilityMargin = 0.9;

// Per-vertex products in float, sums over vertices in double (the conjugate gradients' scalars).
inline double dot3(const glm::vec3& a, const glm::vec3& b) { return double(a.x * b.x + a.y * b.y + a.z * b.z); }
}  // namespace

MassSpringModel::MassSpringModel(const TissueMesh& mesh, const Octree& octree, const MassSpringParams& params,
                                 MassSpringIntegrator integrator, MassSpringScope scope)
    : mMesh(mesh),
      mOctree(octree),
      mParams(params),
      mIntegrator(integrator),
      mScope(scope),
      mRingFinder(mesh) {
    const auto errors = validateMassSpringParams(params);
    if (!errors.empty()) {
        std::string text = "invalid mass-spring parameters:";
        for (const auto& e : errors) text += "\n  " + e.message;
        throw std::invalid_argument(text);
    }
    const std::size_t n = mesh.vertexCount();
    mAccelPerN = float(1000.0 / params.vertexMassKg);
    mAnchor = float(params.anchorStiffnessNPerMm);
    mEdge = float(params.edgeStiffnessNPerMm);
    mContactK = float(params.contactStiffnessNPerMm);
    mGamma = float(2.0 * params.dampingRatio * std::sqrt(1000.0 * params.anchorStiffnessNPerMm / params.vertexMassKg));

    // Gershgorin: every eigenvalue of the stiffness matrix is at most max_v (k_a + 2 k_e deg_v)
    // (+ k_c on the touched vertex); omega^2 = eigenvalue * 1000 / m.
    mDegree.resize(n);
    std::uint32_t maxDegree = 0;
    for (std::size_t v = 0; v < n; ++v) {
        mDegree[v] = mesh.neighbourStart()[v + 1] - mesh.neighbourStart()[v];
        maxDegree = std::max(maxDegree, mDegree[v]);
    }
    mOmegaMaxBound = std::sqrt(1000.0 / params.vertexMassKg *
                               (params.anchorStiffnessNPerMm + 2.0 * params.edgeStiffnessNPerMm * maxDegree +
                                params.contactStiffnessNPerMm));

    mU.assign(n, glm::vec3(0.0f));
    mW.assign(n, glm::vec3(0.0f));
    mPositions = mesh.restPositionsMm();
    mSet.resize(n);
    mSlot.assign(n, kNoSlot);
    if (integrator == MassSpringIntegrator::Rk4)
        for (auto* a : {&mUa, &mWa, &mUb, &mWb, &mAccU, &mAccW}) a->assign(n, glm::vec3(0.0f));
    if (integrator == MassSpringIntegrator::BackwardEuler)
        for (auto* a : {&mR, &mP, &mAp}) a->assign(n, glm::vec3(0.0f));
    if (integrator == MassSpringIntegrator::BackwardEuler) mInverseDiagonal.assign(n, 1.0f);
    if (scope == MassSpringScope::Local) {
        mRings = mRingFinder.makeRingSet();
        mRingOf.assign(n, kNotInRing);
    }
    reset();
}

std::string MassSpringModel::name() const {
    if (mScope == MassSpringScope::Local) return "mass-spring-local";
    return "mass-spring-" + std::string(integratorName(mIntegrator));
}

void MassSpringModel::reset() {
    const std::size_t n = mMesh.vertexCount();
    std::fill(mU.begin(), mU.end(), glm::vec3(0.0f));
    std::fill(mW.begin(), mW.end(), glm::vec3(0.0f));
    for (auto* a : {&mUa, &mWa, &mUb, &mWb, &mAccU, &mAccW, &mR, &mP, &mAp}) std::fill(a->begin(), a->end(), glm::vec3(0.0f));
    std::copy(mMesh.restPositionsMm().begin(), mMesh.restPositionsMm().end(), mPositions.begin());
    if (mScope == MassSpringScope::Whole) {
        for (std::size_t v = 0; v < n; ++v) {
            mSet[v] = VertexId(v);
            mSlot[v] = std::uint32_t(v);
        }
        mSetCount = n;
    } else {
        std::fill(mSlot.begin(), mSlot.end(), kNoSlot);
        mSetCount = 0;
        std::fill(mRingOf.begin(), mRingOf.end(), kNotInRing);
        mRings.ringCount = 0;
        mRings.ringStart[1] = 0;
        mRingCentre = kNoVertex;
    }
    mTouched = kNoVertex;
    mContact = false;
    mContactForceN = 0.0f;
    mMaxDisplacementMm = 0.0f;
    mLastCgIterations = 0;
    mLastCgConverged = true;
}

void MassSpringModel::addToSet(VertexId v) {
    if (mSlot[v] != kNoSlot) return;
    mSlot[v] = std::uint32_t(mSetCount);
    mSet[mSetCount++] = v;
}

void MassSpringModel::removeFromSetAt(std::size_t slot) {
    const VertexId v = mSet[slot];
    // Back to exactly rest, and zero in every work array (neighbours read them as pinned values).
    mU[v] = mW[v] = glm::vec3(0.0f);
    for (auto* a : {&mUa, &mWa, &mUb, &mWb, &mAccU, &mAccW, &mR, &mP, &mAp})
        if (!a->empty()) (*a)[v] = glm::vec3(0.0f);
    mPositions[v] = mMesh.restPositionsMm()[v];
    const VertexId last = mSet[--mSetCount];
    mSet[slot] = last;
    mSlot[last] = std::uint32_t(slot);
    mSlot[v] = kNoSlot;
}

void MassSpringModel::updateRings(VertexId touched) {
    if (touched == mRingCentre) return;
    for (std::size_t i = 0, n = mRings.size(); i < n; ++i) mRingOf[mRings.vertices[i]] = kNotInRing;
    mRingFinder.find(touched, mParams.localRingCount, mRings);
    for (int r = 0; r <= mRings.ringCount; ++r)
        for (VertexId v : mRings.ring(r)) {
            mRingOf[v] = std::uint8_t(r);
            addToSet(v);
        }
    mRingCentre = touched;
}

void MassSpringModel::setVertexState(VertexId v, const glm::vec3& displacementMm, const glm::vec3& velocityMmPerS) {
    if (v >= mMesh.vertexCount()) throw std::out_of_range("setVertexState: no vertex " + std::to_string(v));
    addToSet(v);
    mU[v] = displacementMm;
    mW[v] = velocityMmPerS;
    mPositions[v] = mMesh.restPositionsMm()[v] + displacementMm;
    mMaxDisplacementMm = std::max(mMaxDisplacementMm, glm::length(displacementMm));
}

int MassSpringModel::substepsFor(double dtS) const {
    if (mIntegrator == MassSpringIntegrator::BackwardEuler) return 1;
    if (mParams.substeps > 0) return mParams.substeps;
    const double bound = mIntegrator == MassSpringIntegrator::Rk4 ? kRk4Bound : kSymplecticBound;
    const double needed = std::ceil(dtS * mOmegaMaxBound / (kStabilityMargin * bound));
    return int(std::clamp(needed, 1.0, double(mParams.maxSubsteps)));
}

// Spring force on vertex v (N) for displacements u: anchor, edges (a neighbour outside the set reads
// zero: pinned at rest), and the penalty contact on the touched vertex (only pushes, never pulls).
glm::vec3 MassSpringModel::force(const glm::vec3* u, VertexId v, const Contact& contact) const {
    const std::uint32_t* start = mMesh.neighbourStart().data();
    const VertexId* nb = mMesh.neighbours().data();
    glm::vec3 sum(0.0f);
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) sum += u[nb[k]];
    glm::vec3 f = -mAnchor * u[v] - mEdge * (float(mDegree[v]) * u[v] - sum);
    if (contact.valid && v == contact.vertex) {
        const float penetration = contact.depthMm + glm::dot(u[v], contact.normal);
        if (penetration > 0.0f) f -= (mContactK * penetration) * contact.normal;
    }
    return f;
}

void MassSpringModel::stepSymplectic(float h, const Contact& contact) {
    // Velocity first, from the current displacements, then the displacements from the new
    // velocities. The damping term is taken implicitly (w / (1 + h gamma)): with gamma = 0 this is
    // plain symplectic Euler, with gamma > 0 it only removes energy.
    const float damp = 1.0f / (1.0f + h * mGamma);
    const float hc = h * mAccelPerN;
    const glm::vec3* u = mU.data();
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        mW[v] = (mW[v] + hc * force(u, v, contact)) * damp;
    }
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        mU[v] += h * mW[v];
    }
}

void MassSpringModel::stepRk4(float h, const Contact& contact) {
    // y' = (w, a(u) - gamma w); four stages, each reading the previous stage's displacements
    // (neighbours included) and writing the next one's into the other buffer.
    const float c = mAccelPerN, g = mGamma;
    auto stage = [&](const glm::vec3* us, const glm::vec3* ws, glm::vec3* uNext, glm::vec3* wNext, float toNext,
                     float weight, bool first) {
        for (std::size_t i = 0; i < mSetCount; ++i) {
            const VertexId v = mSet[i];
            const glm::vec3 du = ws[v];
            const glm::vec3 dw = c * force(us, v, contact) - g * ws[v];
            if (first) {
                mAccU[v] = du;
                mAccW[v] = dw;
            } else {
                mAccU[v] += weight * du;
                mAccW[v] += weight * dw;
            }
            if (uNext) {
                uNext[v] = mU[v] + toNext * du;
                wNext[v] = mW[v] + toNext * dw;
            }
        }
    };
    stage(mU.data(), mW.data(), mUa.data(), mWa.data(), 0.5f * h, 1.0f, true);
    stage(mUa.data(), mWa.data(), mUb.data(), mWb.data(), 0.5f * h, 2.0f, false);
    stage(mUb.data(), mWb.data(), mUa.data(), mWa.data(), h, 2.0f, false);
    stage(mUa.data(), mWa.data(), nullptr, nullptr, 0.0f, 1.0f, false);
    const float sixth = h / 6.0f;
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        mU[v] += sixth * mAccU[v];
        mW[v] += sixth * mAccW[v];
    }
}

void MassSpringModel::stepBackwardEuler(float h, const Contact& contact) {
    // Baraff-Witkin: w+ = w + h (c f(u + h w+) - gamma w+). The forces are linear in u (the
    // contact too, while it is active; whether it is, is decided at the start of the tick), so
    // with f(u) = -K u + f0:  A w+ = b,  A = (1 + h gamma) I + h^2 c K,  b = w + h c f(u).
    // A is symmetric positive definite: Jacobi-preconditioned conjugate gradients, warm-started
    // at w, over the simulated set (vertices outside it are pinned: zero in every vector).
    const std::uint32_t* start = mMesh.neighbourStart().data();
    const VertexId* nb = mMesh.neighbours().data();
    const bool contactActive = contact.valid && contact.depthMm + glm::dot(mU[contact.vertex], contact.normal) > 0.0f;
    const float h2c = h * h * mAccelPerN;
    const float base = 1.0f + h * mGamma;
    auto applyA = [&](const glm::vec3* x, VertexId v) {
        glm::vec3 sum(0.0f);
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) sum += x[nb[k]];
        glm::vec3 kx = mAnchor * x[v] + mEdge * (float(mDegree[v]) * x[v] - sum);
        if (contactActive && v == contact.vertex) kx += (mContactK * glm::dot(contact.normal, x[v])) * contact.normal;
        return base * x[v] + h2c * kx;
    };
    // Jacobi preconditioner: 1 / diag(A), per vertex for the step size (the contact vertex's own).
    if (h != mInverseDiagonalH) {
        for (std::size_t v = 0; v < mInverseDiagonal.size(); ++v)
            mInverseDiagonal[v] = 1.0f / (base + h2c * (mAnchor + mEdge * float(mDegree[v])));
        mInverseDiagonalH = h;
    }
    glm::vec3 contactInverseDiagonal(0.0f);
    if (contactActive)
        contactInverseDiagonal = 1.0f / (glm::vec3(1.0f / mInverseDiagonal[contact.vertex]) +
                                         (h2c * mContactK) * (contact.normal * contact.normal));
    auto inverseDiagonal = [&](VertexId v) {
        return contactActive && v == contact.vertex ? contactInverseDiagonal : glm::vec3(mInverseDiagonal[v]);
    };

    // r = b - A w (w is the initial guess), p = M^-1 r.
    const float hc = h * mAccelPerN;
    const glm::vec3* u = mU.data();
    double bNorm2 = 0.0, rz = 0.0;
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        const glm::vec3 b = mW[v] + hc * force(u, v, contactActive ? contact : Contact{});
        bNorm2 += dot3(b, b);
        mR[v] = b;  // A w is subtracted below, once every b is known
    }
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        mR[v] -= applyA(mW.data(), v);
        mP[v] = mR[v] * inverseDiagonal(v);
        rz += dot3(mR[v], mP[v]);
    }
    const double tol2 = mParams.cgTolerance * mParams.cgTolerance * bNorm2;
    int iteration = 0;
    double rr = 0.0;
    for (std::size_t i = 0; i < mSetCount; ++i) rr += dot3(mR[mSet[i]], mR[mSet[i]]);
    while (rr > tol2 && iteration < mParams.cgMaxIterations && rz > 0.0) {
        double pAp = 0.0;
        for (std::size_t i = 0; i < mSetCount; ++i) {
            const VertexId v = mSet[i];
            mAp[v] = applyA(mP.data(), v);
            pAp += dot3(mP[v], mAp[v]);
        }
        if (!(pAp > 0.0)) break;
        const float alpha = float(rz / pAp);
        double rzNext = 0.0;
        rr = 0.0;
        for (std::size_t i = 0; i < mSetCount; ++i) {
            const VertexId v = mSet[i];
            mW[v] += alpha * mP[v];
            mR[v] -= alpha * mAp[v];
            rr += dot3(mR[v], mR[v]);
            rzNext += dot3(mR[v], mR[v] * inverseDiagonal(v));
        }
        const float beta = float(rzNext / rz);
        rz = rzNext;
        for (std::size_t i = 0; i < mSetCount; ++i) {
            const VertexId v = mSet[i];
            mP[v] = mR[v] * inverseDiagonal(v) + beta * mP[v];
        }
        ++iteration;
    }
    mLastCgIterations = iteration;
    mLastCgConverged = rr <= tol2;
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        mU[v] += h * mW[v];
    }
}

TickResult MassSpringModel::step(const glm::vec3& tool, double dtS) {
    const FlushDenormals flush;  // the dent's far tail decays into subnormals (FlushDenormals.h)
    const bool toolValid = std::isfinite(tool.x) && std::isfinite(tool.y) && std::isfinite(tool.z);
    const auto& rest = mMesh.restPositionsMm();
    // The touched vertex: exact over the current positions, no vertex being farther than
    // mMaxDisplacementMm from rest (OctreeQueries.h).
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = nearestWithBoundedDisplacement(mOctree, tool, mPositions, mMaxDisplacementMm, mTouched);
        if (found != kNoVertex) touched = found;
    }
    Contact contact;
    if (toolValid && touched != kNoVertex) {
        contact.valid = true;
        contact.vertex = touched;
        contact.normal = mMesh.restNormals()[touched];
        contact.depthMm = glm::dot(rest[touched] - tool, contact.normal);
        if (mScope == MassSpringScope::Local) updateRings(touched);
    }
    TickResult result;
    result.touched = touched;
    if (contact.valid) result.penetrationMm = contact.depthMm + glm::dot(mU[touched], contact.normal);

    // A non-positive or non-finite period integrates nothing (the state stays finite).
    const bool integrate = dtS > 0.0 && std::isfinite(dtS);
    const int substeps = integrate ? substepsFor(dtS) : 0;
    const float h = integrate ? float(dtS / substeps) : 0.0f;
    for (int s = 0; s < substeps; ++s) {
        switch (mIntegrator) {
            case MassSpringIntegrator::SymplecticEuler: stepSymplectic(h, contact); break;
            case MassSpringIntegrator::Rk4: stepRk4(h, contact); break;
            case MassSpringIntegrator::BackwardEuler: stepBackwardEuler(h, contact); break;
        }
    }

    // Positions, the displacement bound for the next search, and (local) the vertices that left
    // the rings and came to rest leave the set.
    float maxDisplacement2 = 0.0f;
    const float eps = float(mParams.restEpsilonMm);
    const float eps2 = eps * eps;
    for (std::size_t i = 0; i < mSetCount;) {
        const VertexId v = mSet[i];
        const glm::vec3 u = mU[v];
        const float u2 = glm::dot(u, u);
        if (mScope == MassSpringScope::Local && mRingOf[v] == kNotInRing && u2 < eps2) {
            const glm::vec3 stepMm = (h * float(substeps)) * mW[v];
            if (glm::dot(stepMm, stepMm) < eps2) {
                removeFromSetAt(i);  // moves the last one into slot i
                continue;
            }
        }
        mPositions[v] = rest[v] + u;
        maxDisplacement2 = std::max(maxDisplacement2, u2);
        ++i;
    }
    mMaxDisplacementMm = std::sqrt(maxDisplacement2);

    // The rendered force is the contact's reaction on the tool: k_c times the penetration below
    // the displaced touched vertex, along its rest normal (out of the tissue).
    float forceN = 0.0f;
    if (contact.valid) forceN = mContactK * std::max(0.0f, contact.depthMm + glm::dot(mU[touched], contact.normal));
    mTouched = touched;
    mContact = forceN > 0.0f;
    mContactForceN = forceN;
    result.contact = mContact;
    if (mContact) result.forceN = forceN * contact.normal;
    return result;
}

double MassSpringModel::energyMilliJ() const {
    // Springs: N/mm * mm^2 = mJ. Kinetic: kg (mm/s)^2 = 1e-6 J = 1e-3 mJ.
    const std::uint32_t* start = mMesh.neighbourStart().data();
    const VertexId* nb = mMesh.neighbours().data();
    double e = 0.0;
    for (std::size_t v = 0; v < mU.size(); ++v) {
        e += 0.5 * mParams.anchorStiffnessNPerMm * dot3(mU[v], mU[v]);
        e += 0.5e-3 * mParams.vertexMassKg * dot3(mW[v], mW[v]);
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
            if (nb[k] < v) continue;  // each edge once
            const glm::vec3 d = mU[v] - mU[nb[k]];
            e += 0.5 * mParams.edgeStiffnessNPerMm * dot3(d, d);
        }
    }
    return e;
}

std::size_t MassSpringModel::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                           std::size_t capacity) const {
    const auto& rest = mMesh.restPositionsMm();
    std::size_t count = 0;
    for (std::size_t i = 0; i < mSetCount; ++i) {
        const VertexId v = mSet[i];
        if (mPositions[v] == rest[v]) continue;
        if (count < capacity) {
            ids[count] = v;
            positionsMm[count] = mPositions[v];
            std::uint8_t ring = kRelaxingRing;
            if (mContact) {
                if (mScope == MassSpringScope::Local)
                    ring = mRingOf[v] == kNotInRing ? kRelaxingRing : mRingOf[v];
                else
                    ring = v == mTouched ? 0 : 1;  // no rings here: 0 the touched vertex, 1 the rest of the dent
            }
            rings[count] = ring;
        }
        ++count;
    }
    return count;
}

}  // namespace palpate
