#pragma once
// Coulomb friction on the tool's proxy (docs/method.md, "Friction"): the proxy sticks to a point
// of the surface while the tangential spring between that point and the frictionless contact
// point pulls with at most mu_s F_n; beyond, it slides, and while it slides it is dragged so that
// the pull is exactly mu_d F_n, until the tool stops pulling it (then it sticks again). The
// tangential spring is the contact's rendered stiffness, so stick feels like the tissue does.
// Real-time safe; zero coefficients give no tangential force.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace palpate {

class ProxyFriction {
public:
    /// Coefficients (mu_d <= mu_s, both >= 0) and the tangential stiffness, N/mm (> 0).
    void setCoefficients(float staticFriction, float dynamicFriction, float stiffnessNPerMm) {
        mStatic = staticFriction;
        mDynamic = dynamicFriction;
        mStiffness = stiffnessNPerMm;
    }

    /// One tick: `contactMm` the frictionless contact point, `normal` the unit normal there,
    /// `normalForceN` >= 0 the normal force rendered. Returns the tangential force on the tool.
    glm::vec3 step(const glm::vec3& contactMm, const glm::vec3& normal, float normalForceN) {
        if (!(normalForceN > 0.0f) || (mStatic == 0.0f && mDynamic == 0.0f) || !(mStiffness > 0.0f)) {
            release(contactMm);
            return glm::vec3(0.0f);
        }
        if (!mHeld) {
            release(contactMm);
            mHeld = true;
        }
        const glm::vec3 offset = contactMm - mStickMm;
        const glm::vec3 tangential = offset - glm::dot(offset, normal) * normal;
        const float length = glm::length(tangential);
        const float pull = mStiffness * length;
        // Sliding goes on until the pull falls below mu_d F_n (the tool stopped pulling: a
        // relative margin keeps the rounding of last tick's drag from counting as that).
        const float limit = mSliding ? mDynamic * normalForceN * (1.0f - kSlideMargin) : mStatic * normalForceN;
        if (pull <= limit || length == 0.0f) {
            mSliding = false;
            return -mStiffness * tangential;
        }
        // Sliding: the stick point is dragged to where the pull is mu_d F_n.
        mSliding = true;
        const glm::vec3 direction = tangential / length;
        const float slidePull = mDynamic * normalForceN;
        mStickMm = contactMm - (slidePull / mStiffness) * direction;
        return -slidePull * direction;
    }

    /// No contact: nothing is held; the next contact sticks where it starts.
    void release(const glm::vec3& contactMm) {
        mHeld = false;
        mSliding = false;
        mStickMm = contactMm;
    }
    /// Where the proxy is held on the rest surface (the contact point itself without friction).
    const glm::vec3& stickMm() const { return mStickMm; }
    bool sliding() const { return mSliding; }

private:
    static constexpr float kSlideMargin = 1e-4f;
    float mStatic = 0.0f, mDynamic = 0.0f, mStiffness = 0.0f;
    glm::vec3 mStickMm{0.0f};
    bool mHeld = false;
    bool mSliding = false;
};

}  // namespace palpate
