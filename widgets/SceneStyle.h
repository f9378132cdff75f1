#pragma once
// Colours, light and marker sizes shared by both renderers, so that their pictures agree.

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace palpate::style {

inline constexpr glm::vec3 kBackground{0.13f, 0.14f, 0.17f};
inline constexpr glm::vec3 kTissue{0.86f, 0.56f, 0.52f};
/// Tint of displaced (pressed) tissue, blended in by displacement.
inline constexpr glm::vec3 kPressed{0.95f, 0.30f, 0.22f};
/// The ring around the touched vertex: drawn unshaded, so tests can look for this exact colour.
inline constexpr glm::vec3 kTouchedHighlight{1.0f, 0.85f, 0.1f};
/// The touched vertex (ring 0) and rings 1..8 of the slope-ring model, each in its own colour: a
/// triangle takes the colour of the lowest ring among its corners (both renderers), shaded like the
/// tissue. The hues stay away from the tissue's pinks and reds and from each other (and, as far as
/// nine hues allow, from the tool and arrow markers), so that tests can tell them apart by
/// chromaticity. Vertices in no ring (at rest or relaxing) keep the displacement tint.
inline constexpr std::size_t kRingColourCount = 9;
inline constexpr std::array<glm::vec3, kRingColourCount> kRingColours{{
    kTouchedHighlight,      // touched vertex: the same yellow as its marker
    {0.45f, 0.95f, 0.20f},  // ring 1: lime
    {0.10f, 0.80f, 0.75f},  // ring 2: teal
    {0.25f, 0.45f, 1.00f},  // ring 3: blue
    {0.65f, 0.35f, 1.00f},  // ring 4: violet
    {1.00f, 0.30f, 0.85f},  // ring 5: magenta
    {1.00f, 0.60f, 0.05f},  // ring 6: orange
    {0.55f, 0.80f, 1.00f},  // ring 7: sky
    {0.95f, 0.95f, 0.55f},  // ring 8: pale yellow
}};
/// Whether ring index `ring` (0 = touched) has a colour; kNoRing and anything past ring 8 do not.
constexpr bool hasRingColour(std::uint8_t ring) { return ring < kRingColourCount; }

/// The rest shape's ghost (on request): a translucent pale surface with brighter edges, shown only
/// where the rest surface stands off the deformed one (over a dent).
inline constexpr glm::vec3 kGhost{0.70f, 0.85f, 1.00f};
inline constexpr float kGhostFillAlpha = 0.22f;
inline constexpr float kGhostWireAlpha = 0.45f;

/// The see-through view (an exercise's lumps shown to the instructor): the tissue's surface is drawn
/// at this opacity over the background, in both renderers, so the lumps drawn inside read as inside.
inline constexpr float kSeeThroughOpacity = 0.4f;

inline constexpr glm::vec3 kTool{0.25f, 0.8f, 1.0f};
inline constexpr glm::vec3 kForceArrow{0.35f, 1.0f, 0.45f};
inline constexpr glm::vec3 kWire{0.0f, 0.0f, 0.0f};
inline constexpr float kWireAlpha = 0.22f;

/// Key light, camera space, pointing from the surface towards the light (upper left, in front).
inline constexpr glm::vec3 kLightDirView{-0.35f, 0.55f, 0.76f};
inline constexpr float kAmbient = 0.28f;
/// The key light's highlight (Blinn-Phong): its strength and exponent, the same in both renderers.
inline constexpr float kSpecular = 0.18f;
inline constexpr float kShininess = 40.0f;
/// Ring colours are lit with more ambient light than the tissue, so that a ring on a face turned away
/// from the light still reads as its colour.
inline constexpr float kRingAmbient = 0.28f;

/// Displacement (mm) at which the pressed tint is full; smaller displacements blend.
inline constexpr float kFullTintDisplacementMm = 0.5f;

inline constexpr float kTouchedMarkerRadiusPx = 8.0f;
inline constexpr float kToolMarkerRadiusPx = 3.5f;
/// Force arrow length per newton as a fraction of the scene's bounding-box diagonal, and its cap.
inline constexpr float kArrowDiagonalsPerN = 0.04f;
inline constexpr float kArrowMaxDiagonals = 0.3f;

/// The outline of the displaced patch (both renderers, on top): the boundary between triangles
/// with a corner moved more than kOutlineDisplacementMm and the rest, a light line on a dark halo,
/// so that the dent reads on any tissue colour. On a fine mesh the patch can be a few pixels wide:
/// then a circle of at least kPatchMarkerMinRadiusPx marks where it is.
inline constexpr float kOutlineDisplacementMm = 0.05f;
inline constexpr glm::vec3 kPatchOutline{1.0f, 1.0f, 1.0f};
inline constexpr float kPatchMarkerMinRadiusPx = 36.0f;

/// The force label: text in the arrow's colour on an opaque dark plate (contrast ratio well above
/// the 4.5 that WCAG asks for text), in pixels so it is the same size on every paint device.
inline constexpr glm::vec3 kLabelPlate{0.06f, 0.07f, 0.08f};
inline constexpr int kLabelFontPx = 15;

/// The ring legend (bottom left): swatch size and margins in logical pixels.
inline constexpr int kLegendSwatchPx = 10;
inline constexpr int kLegendMarginPx = 8;

}  // namespace palpate::style
