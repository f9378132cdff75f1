#include "widgets/OrbitCamera.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {
constexpr float kDegreesPerPixel = 0.4f;
constexpr float kZoomPerStep = 0.88f;  // distance factor per wheel notch
constexpr float kMaxPitchDeg = 89.0f;  // stay off the poles, where the turntable's up vector flips
constexpr float kFitMargin = 1.05f;    // a little air around the mesh
}  // namespace

glm::mat4 OrbitCamera::rotation() const {
    return glm::lookAt(glm::vec3(0.0f), mTargetMm - eyeMm(), glm::vec3(0.0f, 1.0f, 0.0f));
}

void OrbitCamera::frame(std::span<const glm::vec3> pointsMm) {
    if (pointsMm.empty()) return;
    glm::vec3 lo = pointsMm.front(), hi = pointsMm.front();
    for (const auto& p : pointsMm) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    mSceneRadiusMm = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    mTargetMm = 0.5f * (lo + hi);
    // Fit the points themselves, not a bounding sphere or box: an elongated, curved organ would
    // otherwise fill half the view. The narrower field of view is used for both axes (projection()
    // gives it to the narrower side), so the fit holds for any aspect.
    const glm::mat4 toCamera = rotation();
    const float tanHalfFov = std::tan(glm::radians(0.5f * kFieldOfViewDeg));
    auto requiredDistanceMm = [&] {
        float distanceMm = 1e-3f;
        for (const auto& p : pointsMm) {
            const glm::vec3 c = glm::vec3(toCamera * glm::vec4(p - mTargetMm, 0.0f));
            // The eye, at +distance on the camera's z, must see the point inside the frustum.
            distanceMm = std::max(distanceMm, std::max(std::abs(c.x), std::abs(c.y)) / tanHalfFov + c.z);
        }
        return distanceMm;
    };
    // The box centre does not project to the picture's centre: shift the target sideways by the middle
    // of the points' extent on screen, then fit again from there.
    const float distanceMm = requiredDistanceMm();
    glm::vec2 screenLo(1e9f), screenHi(-1e9f);
    for (const auto& p : pointsMm) {
        const glm::vec3 c = glm::vec3(toCamera * glm::vec4(p - mTargetMm, 0.0f));
        const glm::vec2 s = glm::vec2(c) / std::max(distanceMm - c.z, 1e-3f);
        screenLo = glm::min(screenLo, s);
        screenHi = glm::max(screenHi, s);
    }
    const glm::vec2 shift = 0.5f * (screenLo + screenHi) * distanceMm;
    const glm::mat4 toWorld = glm::transpose(toCamera);
    mTargetMm += glm::vec3(toWorld * glm::vec4(shift.x, shift.y, 0.0f, 0.0f));
    mDistanceMm = kFitMargin * requiredDistanceMm();
}

void OrbitCamera::reset(std::span<const glm::vec3> pointsMm) {
    mYawDeg = kDefaultYawDeg;
    mPitchDeg = kDefaultPitchDeg;
    frame(pointsMm);
}

void OrbitCamera::orbit(float dxPx, float dyPx) {
    mYawDeg = std::fmod(mYawDeg - dxPx * kDegreesPerPixel, 360.0f);
    mPitchDeg = std::clamp(mPitchDeg + dyPx * kDegreesPerPixel, -kMaxPitchDeg, kMaxPitchDeg);
}

void OrbitCamera::zoom(float steps) {
    const float minDistanceMm = 0.05f * mSceneRadiusMm;
    const float maxDistanceMm = 20.0f * mSceneRadiusMm;
    mDistanceMm = std::clamp(mDistanceMm * std::pow(kZoomPerStep, steps), minDistanceMm, maxDistanceMm);
}

float OrbitCamera::mmPerPixelAtTarget(const glm::vec2& sizePx) const {
    // projection() gives the field of view to the narrower side; pixels are square.
    const float narrowPx = std::max(std::min(sizePx.x, sizePx.y), 1.0f);
    return 2.0f * mDistanceMm * std::tan(glm::radians(0.5f * kFieldOfViewDeg)) / narrowPx;
}

void OrbitCamera::pan(float dxPx, float dyPx, const glm::vec2& sizePx) {
    const float mmPerPx = mmPerPixelAtTarget(sizePx);
    const glm::mat4 toWorld = glm::transpose(rotation());
    const glm::vec3 right = glm::vec3(toWorld * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    const glm::vec3 up = glm::vec3(toWorld * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    // Dragging right moves the picture right: the camera goes left. Screen y points down.
    mTargetMm += mmPerPx * (-dxPx * right + dyPx * up);
}

OrbitCamera::Ray OrbitCamera::rayThroughPixel(const glm::vec2& pixel, const glm::vec2& sizePx) const {
    const glm::vec2 size = glm::max(sizePx, glm::vec2(1.0f));
    const glm::vec2 ndc{2.0f * pixel.x / size.x - 1.0f, 1.0f - 2.0f * pixel.y / size.y};
    const glm::mat4 inverse = glm::inverse(projection(size.x / size.y) * view());
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
    // From the eye rather than the near plane: nothing in front of the near plane is lost.
    const glm::vec3 eye = eyeMm();
    return {eye, glm::normalize(b - a)};
}

glm::vec3 OrbitCamera::eyeMm() const {
    const float yaw = glm::radians(mYawDeg), pitch = glm::radians(mPitchDeg);
    const glm::vec3 offset{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
    return mTargetMm + mDistanceMm * offset;
}

glm::mat4 OrbitCamera::view() const {
    return glm::lookAt(eyeMm(), mTargetMm, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    aspect = std::max(aspect, 1e-3f);
    float fovY = glm::radians(kFieldOfViewDeg);
    if (aspect < 1.0f) fovY = 2.0f * std::atan(std::tan(0.5f * fovY) / aspect);  // keep the horizontal fov
    // Near and far hug the scene so that the depth buffer keeps its precision where the mesh is.
    const float nearMm = std::max(mDistanceMm - 2.0f * mSceneRadiusMm, 0.01f * mDistanceMm);
    const float farMm = mDistanceMm + 2.0f * mSceneRadiusMm;
    return glm::perspective(fovY, aspect, nearMm, farMm);
}

std::optional<glm::vec2> OrbitCamera::projectToPixel(const glm::vec3& pointMm, const glm::vec2& sizePx) const {
    return PixelProjection(*this, sizePx)(pointMm);
}

OrbitCamera::PixelProjection::PixelProjection(const OrbitCamera& camera, const glm::vec2& sizePx)
    : mViewProjection(camera.projection(sizePx.x / std::max(sizePx.y, 1.0f)) * camera.view()), mSizePx(sizePx) {}

std::optional<glm::vec2> OrbitCamera::PixelProjection::operator()(const glm::vec3& pointMm) const {
    const glm::vec4 clip = mViewProjection * glm::vec4(pointMm, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    const glm::vec2 ndc{clip.x / clip.w, clip.y / clip.w};
    return glm::vec2{(ndc.x * 0.5f + 0.5f) * mSizePx.x, (0.5f - ndc.y * 0.5f) * mSizePx.y};
}

}  // namespace palpate
