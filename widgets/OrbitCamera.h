#pragma once
// A turntable camera around a target point: what both viewports render with, so that the OpenGL and
// the software renderer show the same picture. Qt-free (glm), so it can be tested without a GUI.

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <span>

namespace palpate {

class OrbitCamera {
public:
    /// The view a reset returns to: from above (+y) and turned towards +x, where the scripted tool
    /// path presses; the shipped stomach meshes lie in the x-z plane.
    static constexpr float kDefaultYawDeg = 80.0f;
    static constexpr float kDefaultPitchDeg = 40.0f;
    /// Vertical field of view, or horizontal when the viewport is taller than wide.
    static constexpr float kFieldOfViewDeg = 40.0f;

    /// Frames the points from the current angles: aims at their centre on screen and moves back until
    /// all are inside the view (for any aspect). Does nothing for no points.
    void frame(std::span<const glm::vec3> pointsMm);
    /// Default angles, then `frame`.
    void reset(std::span<const glm::vec3> pointsMm);

    /// Turns the camera by a mouse drag: horizontal pixels change the yaw, vertical the pitch.
    void orbit(float dxPx, float dyPx);
    /// Moves towards (steps > 0) or away from the target; one wheel notch is one step.
    void zoom(float steps);
    /// Slides the camera and its target sideways by a mouse drag of (dxPx, dyPx) in a viewport of
    /// `sizePx`, so that what lies at the target's depth follows the mouse. Reset and fit undo it.
    void pan(float dxPx, float dyPx, const glm::vec2& sizePx);

    float yawDeg() const { return mYawDeg; }
    float pitchDeg() const { return mPitchDeg; }
    float distanceMm() const { return mDistanceMm; }
    glm::vec3 targetMm() const { return mTargetMm; }
    glm::vec3 eyeMm() const;

    /// World (mm) to camera space; a rigid transform, so its upper 3x3 also maps normals.
    glm::mat4 view() const;
    /// OpenGL clip-space projection for a viewport of width / height `aspect`.
    glm::mat4 projection(float aspect) const;

    /// Where a world point lands in a viewport of `sizePx` (origin top left, y down); nullopt when
    /// it is behind the near plane.
    std::optional<glm::vec2> projectToPixel(const glm::vec3& pointMm, const glm::vec2& sizePx) const;
    /// projectToPixel for many points of one frame: the matrices are built once, not per point.
    class PixelProjection {
    public:
        PixelProjection(const OrbitCamera& camera, const glm::vec2& sizePx);
        std::optional<glm::vec2> operator()(const glm::vec3& pointMm) const;

    private:
        glm::mat4 mViewProjection;
        glm::vec2 mSizePx;
    };
    /// The inverse: the ray from the eye through `pixel` (same coordinates as projectToPixel; the
    /// centre of pixel (i, j) is (i + 0.5, j + 0.5)). The direction is normalised.
    struct Ray {
        glm::vec3 originMm;
        glm::vec3 direction;
    };
    Ray rayThroughPixel(const glm::vec2& pixel, const glm::vec2& sizePx) const;
    /// World size (mm) of one pixel at the target's depth, in a viewport of `sizePx`.
    float mmPerPixelAtTarget(const glm::vec2& sizePx) const;

private:
    /// Rotation from world to camera axes (x right, y up, -z forward).
    glm::mat4 rotation() const;

    glm::vec3 mTargetMm{0.0f};
    float mSceneRadiusMm = 86.6f;
    float mDistanceMm = 250.0f;
    float mYawDeg = kDefaultYawDeg;
    float mPitchDeg = kDefaultPitchDeg;
};

}  // namespace palpate
