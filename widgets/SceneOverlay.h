#pragma once
// The markers drawn over the mesh by both renderers with QPainter: the touched vertex, the tool tip,
// the force arrow and its label, the outline of the displaced patch, and a legend of the ring
// colours and the dent's depth. Drawn on top without depth test: they are a cursor, and must never hide.

#include <QColor>
#include <QRectF>
#include <QSize>
#include <QString>

#include <glm/vec3.hpp>

class QPainter;

namespace palpate {

class OrbitCamera;
class RenderScene;

QColor toQColor(const glm::vec3& rgb, float alpha = 1.0f);

/// The legend's label for ring index `ring` (0: "touched", then "ring 1", ...).
QString ringLegendLabel(int ring);

/// WCAG 2 contrast ratio of two opaque colours, 1..21 (4.5 is the least it asks of text).
double contrastRatio(const QColor& a, const QColor& b);

/// The deepest displacement from rest now (mm), over all vertices.
float deepestDisplacementMm(const RenderScene& scene);

/// Where the force label's plate goes in a viewport of `sizePx` (logical pixels), or an empty
/// rectangle when there is no force to show. Beside the displaced patch, never over it.
QRectF forceLabelRect(const RenderScene& scene, const OrbitCamera& camera, QSize sizePx);

/// The pixel bounds of the displaced patch's outline in a viewport of `sizePx` (logical pixels),
/// empty when nothing is displaced.
QRectF displacedPatchRect(const RenderScene& scene, const OrbitCamera& camera, QSize sizePx);

/// Where the legend goes in a viewport of `sizePx` (bottom left), or an empty rectangle when there
/// is none: it lists the touched vertex and the rings up to the highest one present (and the ghost
/// when shown), so it appears in contact.
QRectF sceneLegendRect(const RenderScene& scene, QSize sizePx, bool showRestGhost = false);

/// Paints the overlay for a viewport of `sizePx` (logical pixels) seen through `camera`.
void paintSceneOverlay(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, QSize sizePx,
                       bool showRestGhost = false);

}  // namespace palpate
