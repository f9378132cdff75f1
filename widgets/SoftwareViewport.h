#pragma once
// The viewport drawn with QPainter: flat-shaded triangles sorted back to front (painter's algorithm),
// each in the colour of its lowest ring, the rest-shape ghost on request, with the same camera,
// colours, markers and picking as MeshViewport. Used where OpenGL is missing (Qt's
// offscreen platform, widget tests, remote sessions) or when --software-render is given.

#include "widgets/Viewport.h"

#include <QWidget>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace palpate {

class SoftwareViewport final : public QWidget, public Viewport {
    Q_OBJECT
public:
    explicit SoftwareViewport(QWidget* parent = nullptr);

    QWidget* widget() override { return this; }
    RendererKind kind() const override { return RendererKind::Software; }
    QImage grabImage() override;

    QSize sizeHint() const override { return {800, 600}; }

protected:
    void sceneChanged(bool topologyChanged) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void paintScene(QPainter& painter, QSize sizePx);

    // Scratch kept between frames so that painting does not allocate.
    struct ProjectedVertex {
        float xPx, yPx;
        bool inFront;  // in front of the near plane
    };
    std::vector<ProjectedVertex> mProjected;
    std::vector<glm::vec3> mViewMm;
    /// Marks a ghost (rest-shape) triangle in mOrder.
    static constexpr std::uint32_t kGhostBit = 0x80000000u;
    std::vector<std::pair<float, std::uint32_t>> mOrder;  // (camera-space depth, triangle | kGhostBit)
};

}  // namespace palpate
