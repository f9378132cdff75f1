#pragma once
// The markers drawn over the mesh by both renderers with QPainter: the touched vertex, the tool tip
// and the force arrow. Drawn on top without depth test: they are a cursor, and must never hide.

#include <QColor>
#include <QSize>

#include <glm/vec3.hpp>

class QPainter;

namespace palpate {

class OrbitCamera;
class RenderScene;

QColor toQColor(const glm::vec3& rgb, float alpha = 1.0f);

/// Paints the overlay for a viewport of `sizePx` (logical pixels) seen through `camera`.
void paintSceneOverlay(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, QSize sizePx);

}  // namespace palpate
