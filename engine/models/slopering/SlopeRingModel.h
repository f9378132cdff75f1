#pragma once
// The slope-ring model: the touched vertex and its rings move by p = p_rest + m_r F (the paper's
// Eq. (1)-(3), m_r < 0), return springs tie them to rest, and the touched vertex's spring
// reaction is the force rendered (docs/method.md). This base holds what every slope-ring method
// shares: the parameters and their hot constants, the contact force update, the return springs'
// relaxation and the rendered force. The methods (PaperSlopeRing: the paper's three;
// CoherentSlopeRing: ours) differ only in the search and in how much work a tick does.

#include "engine/models/ContactDef.h"
#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace palpate {

/// copyDisplaced's output arrays: puts a vertex while there is room, counts every one (a count
/// above the capacity tells the caller the copy was cut).
struct DisplacedOutput {
    VertexId* ids;
    glm::vec3* positionsMm;
    std::uint8_t* rings;
    std::size_t capacity;
    std::size_t count = 0;

    void put(VertexId v, const glm::vec3& positionMm, std::uint8_t ring) {
        if (count < capacity) {
            ids[count] = v;
            positionsMm[count] = positionMm;
            rings[count] = ring;
        }
        ++count;
    }
};

class SlopeRingModel : public DeformationModel {
public:
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    std::string name() const override;
    /// Real-time: takes a slope-ring definition of this model's method when the method can take it
    /// without reallocating (see canTakeParams); false otherwise (the caller rebuilds the model).
    bool applyModelParams(const ModelDef& def) override;

    /// Replaces the parameters (validated first; throws std::invalid_argument listing every problem).
    /// Not real-time: may precompute rings.
    void setParams(const SlopeRingParams& params);
    /// The tool and friction (ours only; the paper's methods touch with a point, without
    /// friction, and ignore it). Already validated (validateModelDef). Real-time safe.
    virtual void setContact(const ContactDef& /*contact*/) {}
    const SlopeRingParams& params() const { return mParams; }
    SlopeRingMethod method() const { return mMethod; }
    const TissueMesh& mesh() const { return mMesh; }

    /// The touched vertex this method's search would report now, without changing the deformation
    /// (kNoVertex where the paper's searchNode finds nothing).
    virtual VertexId findTouched(const glm::vec3& toolTipMm) const = 0;
    VertexId touchedVertex() const { return mTouched; }
    /// Contact force magnitude of the slope model (N), before the spring rendering.
    float contactForceN() const { return mContactForceN; }
    /// Coherent: every vertex that may be away from rest (the active rings and those relaxing).
    /// The paper's methods: empty (they keep no such list). Not real-time.
    virtual std::span<const VertexId> displacedVertices() const { return {}; }

protected:
    /// `mesh` and `octree` must outlive the model. The derived constructor calls setParams.
    SlopeRingModel(const TissueMesh& mesh, const Octree& octree, SlopeRingMethod method);

    /// Whether already validated parameters can be taken at a tick boundary (no reallocation).
    virtual bool canTakeParams(const SlopeRingParams& params) const = 0;
    /// After the parameters changed (setParams, or applyModelParams in real time): `ringsChanged`
    /// when the ring count did.
    virtual void paramsReplaced(bool ringsChanged) = 0;

    /// Back to rest: positions, velocities, the contact. The derived reset() calls it.
    void resetShared();

    /// The start of a tick: the relaxation's factors for this period.
    void prepareTick(double dtS) {
        if (dtS != mRelaxDtS) {
            mRelaxDtS = dtS;
            mRelaxDt = float(dtS);
            mRelaxDenominatorInv = 1.0f / (1.0f + mRelaxDt * mHot.twoZetaOmega + mRelaxDt * mRelaxDt * mHot.omega2);
        }
    }
    static bool isFinite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

    /// The contact and the contact force (docs/method.md): d = depth of the tip below the touched
    /// vertex's rest position along its rest normal; the model displaces that vertex by |m1| F, so
    /// the tip is e = d - |m1| F below it. F <- max(0, (1 - alpha) F + alpha k_c e); contact while
    /// F > 0. A stiffer inclusion scales the touched vertex's slopes by `compliance` c in (0, 1]:
    /// the tip is d - c |m1| F below it, and the exact solve uses the gain c |m1| k_c (c = 1: the
    /// paper's model). Sets the touched vertex, the force and the contact; returns the penetration.
    float updateContact(const glm::vec3& tool, bool toolValid, VertexId touched, float compliance) {
        const bool touching = toolValid && touched != kNoVertex;
        const float depth =
            touching ? glm::dot(mMesh.restPositionsMm()[touched] - tool, mMesh.restNormals()[touched]) : 0.0f;
        const float penetration = updateContactForce(depth, touching, compliance);
        mTouched = touched;
        return penetration;
    }

    /// The contact force update alone, for a rest depth `depthMm` (of the tip below the touched
    /// point's rest position, along its normal) found by the caller: returns the penetration into
    /// the displaced surface, d - c |m1| F, and updates F and the contact. `touching` false: no
    /// contact point, F = 0.
    float updateContactForce(float depthMm, bool touching, float compliance) {
        return updateContactForce(depthMm, touching, compliance, 0.0f);
    }

    /// The sink of the contact point under force F (docs/scoring.md, "Lumps under the surface"):
    /// |m1| F on tissue; over a lump whose top lies z below, soft until the sink reaches z and
    /// then stiffer by the contrast, min(|m1| F, c |m1| F + b) with b = (1 - c) z. b = 0 is the
    /// uniform inclusion, c |m1| F.
    float sinkMm(float forceN, float compliance, float offsetMm) const {
        const float soft = -mHot.signedSlope[0] * stiffenedForceN(mHot, forceN);
        return offsetMm > 0.0f ? std::min(soft, compliance * soft + offsetMm) : compliance * soft;
    }

    /// The same for a lump under the surface: `offsetMm` = b above (0: none). The tip meets the
    /// sunk surface where d = sink(F) + F / k_c; the sink is concave and piecewise linear, so the
    /// exact solve is the larger of its two lines' solutions, F = max(k_c d / (1 + g),
    /// k_c (d - b) / (1 + g c)) with g = |m1| k_c; a relaxed update steps toward it and is stable
    /// as the uniform one is (the sink's slope is at most |m1|).
    float updateContactForce(float depthMm, bool touching, float compliance, float offsetMm) {
        if (mHot.stiffeningKnots > 0) {
            const float penetration = touching ? depthMm - sinkMm(mContactForceN, compliance, offsetMm) : 0.0f;
            if (!touching)
                mContactForceN = 0.0f;
            else if (mParams.forceRelaxation > 0.0)
                mContactForceN = std::max(0.0f, (1.0f - mHot.alpha) * mContactForceN +
                                                     mHot.alpha * (mHot.contactStiffness * penetration));
            else
                mContactForceN = stiffenedContactForceN(depthMm, compliance, offsetMm);
            mContact = mContactForceN > 0.0f;
            return penetration;
        }
        if (offsetMm > 0.0f) {
            const float penetration = touching ? depthMm - sinkMm(mContactForceN, compliance, offsetMm) : 0.0f;
            if (!touching) {
                mContactForceN = 0.0f;
            } else if (mParams.forceRelaxation > 0.0) {
                mContactForceN = std::max(0.0f, (1.0f - mHot.alpha) * mContactForceN +
                                                     mHot.alpha * (mHot.contactStiffness * penetration));
            } else {
                const float gain = float(mParams.loopGain());
                const float soft = mHot.contactStiffness * depthMm / (1.0f + gain);
                const float stiff = mHot.contactStiffness * (depthMm - offsetMm) / (1.0f + gain * compliance);
                mContactForceN = std::max({0.0f, soft, stiff});
            }
            mContact = mContactForceN > 0.0f;
            return penetration;
        }
        const float penetration = touching ? depthMm + mHot.signedSlope[0] * (compliance * mContactForceN) : 0.0f;
        const float alpha = compliance == 1.0f || mParams.forceRelaxation > 0.0
                                ? mHot.alpha
                                : float(1.0 / (1.0 + mParams.loopGain() * double(compliance)));
        // Projected onto F >= 0 (the tissue only pushes): a non-expansive step, so the iteration
        // converges wherever its linear part does, alpha (1 + gain) < 2, overshoot or not.
        if (touching)
            mContactForceN = std::max(0.0f,
                                      (1.0f - alpha) * mContactForceN + alpha * (mHot.contactStiffness * penetration));
        else mContactForceN = 0.0f;
        mContact = mContactForceN > 0.0f;
        return penetration;
    }

    /// The exact contact force of stiffening tissue: g(F) = F + k_c sink(F) = k_c d. The sink is
    /// concave and piecewise linear in F (its kinks: the knots, and over a lump the force where the
    /// sink reaches the lump), so g is piecewise linear and rising: walk its kinks, O(knots).
    float stiffenedContactForceN(float depthMm, float compliance, float offsetMm) const {
        const float target = mHot.contactStiffness * depthMm;
        if (!(target > 0.0f)) return 0.0f;
        auto g = [&](float f) { return f + mHot.contactStiffness * sinkMm(f, compliance, offsetMm); };
        // The lump's kink: the soft sink |m1| E(F) reaches the stiff line at E = b / (|m1| (1 - c)).
        float lumpKinkN = -1.0f;
        if (offsetMm > 0.0f && compliance < 1.0f)
            lumpKinkN = unstiffenedForceN(mHot, offsetMm / (-mHot.signedSlope[0] * (1.0f - compliance)));
        float previousF = 0.0f, previousG = 0.0f;
        int knot = 0;
        for (;;) {
            float next;
            const bool haveKnot = knot < mHot.stiffeningKnots;
            if (lumpKinkN > previousF && (!haveKnot || lumpKinkN < mHot.stiffeningForceN[knot])) {
                next = lumpKinkN;
                lumpKinkN = -1.0f;
            } else if (haveKnot) {
                next = mHot.stiffeningForceN[knot++];
            } else {
                break;
            }
            if (!(next > previousF)) continue;
            const float gNext = g(next);
            if (gNext >= target) return previousF + (target - previousG) * (next - previousF) / (gNext - previousG);
            previousF = next;
            previousG = gNext;
        }
        const float slope = g(previousF + 1.0f) - previousG;  // the last piece, per newton
        return previousF + (target - previousG) / slope;
    }

    /// The tick's result; `touchedDisplacementMm` is the touched vertex's displacement from rest,
    /// whose spring reaction is the force rendered.
    TickResult tickResult(VertexId touched, float penetration, const glm::vec3& touchedDisplacementMm) const {
        TickResult result;
        result.touched = touched;
        result.contact = mContact;
        result.penetrationMm = penetration;
        if (mContact) {
            result.forceN = -mHot.springStiffness * touchedDisplacementMm;
            result.normal = mMesh.restNormals()[touched];
        }
        return result;
    }

    /// The slope update (the paper's Eq. (1)-(3)): a vertex of ring `ring` sits at rest + this,
    /// m_r F along the touched vertex's rest normal (m_r < 0: into the tissue).
    glm::vec3 ringDisplacementMm(int ring, float forceN, const glm::vec3& normal) const {
        return (mHot.signedSlope[ring] * stiffenedForceN(mHot, forceN)) * normal;
    }

    /// Backward Euler on m x'' = -k x - c x' for one vertex: unconditionally stable and dissipative.
    void relaxVertex(VertexId v) {
        const glm::vec3 rest = mMesh.restPositionsMm()[v];
        const glm::vec3 u = mPositions[v] - rest;
        glm::vec3& vel = mVelocitiesMmPerS[v];
        vel = (vel - (mRelaxDt * mHot.omega2) * u) * mRelaxDenominatorInv;
        mPositions[v] = rest + (u + mRelaxDt * vel);
    }

    const TissueMesh& mMesh;
    const Octree& mOctree;
    SlopeRingParams mParams;
    const SlopeRingMethod mMethod;
    RingFinder mRingFinder;

    // Hot-loop constants derived from the parameters.
    SlopeRingConstants mHot;  // what the tick reads, derived from mParams
    double mRelaxDtS = -1.0;         // dt for which the two factors below hold
    float mRelaxDenominatorInv = 1.0f, mRelaxDt = 0.0f;

    // mutable: the coherent method writes its active rings here when they are read
    // (positionsMm() const, at display rate); the paper's methods write them in the tick.
    mutable std::vector<glm::vec3> mPositions;
    std::vector<glm::vec3> mVelocitiesMmPerS;

    // State of the contact.
    VertexId mTouched = kNoVertex;
    float mContactForceN = 0.0f;
    bool mContact = false;

private:
    void updateHotConstants();
};

/// The method's class (PaperSlopeRing for previous, hybrid and proposed; CoherentSlopeRing for
/// coherent). Throws std::invalid_argument on bad params. `eagerPositions` (coherent only): see
/// CoherentSlopeRing.
std::unique_ptr<SlopeRingModel> makeSlopeRing(const TissueMesh& mesh, const Octree& octree,
                                              const SlopeRingParams& params,
                                              SlopeRingMethod method = SlopeRingMethod::Coherent,
                                              bool eagerPositions = false);

}  // namespace palpate
