#pragma once
// The markers drawn over the mesh by both renderers with QPainter: the touched vertex, the tool tip,
// the force arrow, and a legend of the ring colours. Drawn on top without depth test: they are a
// cursor, and must never hide.

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

/// Where the legend goes in a viewport of `sizePx` (bottom left), or an empty rectangle when there
/// is none: it lists the touched vertex and the rings up to the highest one present (and the ghost
/// when shown), so it appears in contact.
QRectF sceneLegendRect(const RenderScene& scene, QSize sizePx, bool showRestGhost = false);

/// Paints the overlay for a viewport of `sizePx` (logical pixels) seen through `camera`.
void paintSceneOverlay(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, QSize sizePx,
                       bool showRestGhost = false);

}  // namespace palpate
