#pragma once
// Colours, light and marker sizes shared by both renderers, so that their pictures agree.

#include <glm/vec3.hpp>

namespace palpate::style {

inline constexpr glm::vec3 kBackground{0.13f, 0.14f, 0.17f};
inline constexpr glm::vec3 kTissue{0.86f, 0.56f, 0.52f};
/// Tint of displaced (pressed) tissue, blended in by displacement.
inline constexpr glm::vec3 kPressed{0.95f, 0.30f, 0.22f};
/// The ring around the touched vertex: drawn unshaded, so tests can look for this exact colour.
inline constexpr glm::vec3 kTouchedHighlight{1.0f, 0.85f, 0.1f};
inline constexpr glm::vec3 kTool{0.25f, 0.8f, 1.0f};
inline constexpr glm::vec3 kForceArrow{0.35f, 1.0f, 0.45f};
inline constexpr glm::vec3 kWire{0.0f, 0.0f, 0.0f};
inline constexpr float kWireAlpha = 0.22f;

/// Key light, camera space, pointing from the surface towards the light (upper left, in front).
inline constexpr glm::vec3 kLightDirView{-0.35f, 0.55f, 0.76f};
inline constexpr float kAmbient = 0.28f;

/// Displacement (mm) at which the pressed tint is full; smaller displacements blend.
inline constexpr float kFullTintDisplacementMm = 0.5f;

inline constexpr float kTouchedMarkerRadiusPx = 8.0f;
inline constexpr float kToolMarkerRadiusPx = 3.5f;
/// Force arrow length per newton as a fraction of the scene's bounding-box diagonal, and its cap.
inline constexpr float kArrowDiagonalsPerN = 0.04f;
inline constexpr float kArrowMaxDiagonals = 0.3f;

}  // namespace palpate::style
