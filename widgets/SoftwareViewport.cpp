#include "widgets/SoftwareViewport.h"

#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

/// How far (mm) the rest shape must stand in front of the tissue for its ghost to show: where the
/// two coincide (the barely moved rim of a dent) the tissue wins, as the OpenGL ghost's depth offset does.
constexpr float kGhostMarginMm = 0.05f;

std::uint32_t packRgb(float r, float g, float b) {
    auto channel = [](float v) { return std::uint32_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return 0xff000000u | (channel(r) << 16) | (channel(g) << 8) | channel(b);
}

/// The wire's weight at `distancePx` from an edge: a pixel wide (each side draws its half), fading
/// out over the next half pixel, as mesh.frag draws it.
float wireWeight(float distancePx) {
    if (distancePx <= 0.5f) return 1.0f;
    if (distancePx >= 1.0f) return 0.0f;
    const float t = (distancePx - 0.5f) * 2.0f;
    return 1.0f - t * t * (3.0f - 2.0f * t);
}

struct Corner {
    float x, y, invDepth, diffuse, specular;
};

/// Pixels [x0, x1] x [y0, y1], inclusive.
struct PixelRect {
    int x0, y0, x1, y1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

/// Calls shade(x, y, l0, l1, l2, edgePx, a, b, c) for every pixel centre inside triangle abc and
/// inside `clip`: barycentric weights and the distance in pixels to the nearest
/// edge (only computed when `edges`; else a large number). Shared edges are filled once (top-left
/// rule): no pinholes, no double blending. `backSign` != 0: a triangle whose screen-space area has
/// that sign faces away and is skipped.
template <typename Shade>
void fillTriangle(Corner a, Corner b, Corner c, const PixelRect& clip, int backSign, bool edges, Shade&& shade) {
    auto orient = [](const Corner& p, const Corner& q, float x, float y) {
        return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
    };
    float area = orient(a, b, c.x, c.y);
    if (area == 0.0f || !std::isfinite(area)) return;
    if (backSign != 0 && (area > 0.0f) == (backSign > 0)) return;
    if (area < 0.0f) {
        std::swap(b, c);
        area = -area;
    }
    const int minX = std::max(clip.x0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int maxX = std::min(clip.x1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int minY = std::max(clip.y0, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int maxY = std::min(clip.y1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    if (minX > maxX || minY > maxY) return;
    // Edge k is opposite corner k. In screen space (y down) with positive area, an edge is "top"
    // when horizontal with the triangle below it, "left" when it goes up.
    auto topLeft = [](const Corner& p, const Corner& q) { return (p.y == q.y && q.x < p.x) || q.y < p.y; };
    const float bias0 = topLeft(b, c) ? 0.0f : -1e-7f, bias1 = topLeft(c, a) ? 0.0f : -1e-7f,
                bias2 = topLeft(a, b) ? 0.0f : -1e-7f;
    auto inverseLength = [edges](float dx, float dy) {
        return edges ? 1.0f / std::max(std::sqrt(dx * dx + dy * dy), 1e-6f) : 0.0f;
    };
    const float inv0 = inverseLength(c.x - b.x, c.y - b.y);
    const float inv1 = inverseLength(a.x - c.x, a.y - c.y);
    const float inv2 = inverseLength(b.x - a.x, b.y - a.y);
    const float dx0 = b.y - c.y, dx1 = c.y - a.y, dx2 = a.y - b.y;  // per pixel to the right
    const float invArea = 1.0f / area;
    for (int y = minY; y <= maxY; ++y) {
        const float py = float(y) + 0.5f, px = float(minX) + 0.5f;
        float w0 = orient(b, c, px, py), w1 = orient(c, a, px, py), w2 = orient(a, b, px, py);
        // The row's span from the three edges (a pixel of slack each side: the exact test below decides).
        float first = 0.0f, last = float(maxX - minX);
        bool empty = false;
        auto span = [&](float w, float dx) {
            if (dx > 0.0f) first = std::max(first, std::floor(-w / dx) - 1.0f);
            else if (dx < 0.0f) last = std::min(last, std::ceil(-w / dx) + 1.0f);
            else if (w < 0.0f) empty = true;
        };
        span(w0, dx0);
        span(w1, dx1);
        span(w2, dx2);
        if (empty || first > last) continue;
        const int skip = int(first);
        w0 += dx0 * float(skip);
        w1 += dx1 * float(skip);
        w2 += dx2 * float(skip);
        for (int x = minX + skip, end = minX + int(last); x <= end; ++x, w0 += dx0, w1 += dx1, w2 += dx2) {
            if (w0 + bias0 < 0.0f || w1 + bias1 < 0.0f || w2 + bias2 < 0.0f) continue;
            if ((w0 == 0.0f && bias0 < 0.0f) || (w1 == 0.0f && bias1 < 0.0f) || (w2 == 0.0f && bias2 < 0.0f)) continue;
            const float edgePx = edges ? std::min({w0 * inv0, w1 * inv1, w2 * inv2}) : 1e9f;
            shade(x, y, w0 * invArea, w1 * invArea, w2 * invArea, edgePx, a, b, c);
        }
    }
}

/// The corner of a projected vertex (SoftwareViewport::ProjectedVertex) that fillTriangle shades.
template <typename Projected>
Corner corner(const Projected& p) {
    return Corner{p.xPx, p.yPx, p.invDepth, p.diffuse, p.specular};
}

/// Whether triangle abc (projected vertices) may cover a pixel of `region`: a triangle crossing
/// the near plane is dropped rather than clipped.
template <typename Projected>
bool inRegion(const PixelRect& region, const Projected& a, const Projected& b, const Projected& c) {
    if (!a.inFront || !b.inFront || !c.inFront) return false;
    const float rx0 = float(region.x0) - 1.0f, ry0 = float(region.y0) - 1.0f, rx1 = float(region.x1) + 1.0f,
                ry1 = float(region.y1) + 1.0f;
    const float minX = std::min({a.xPx, b.xPx, c.xPx}), maxX = std::max({a.xPx, b.xPx, c.xPx});
    const float minY = std::min({a.yPx, b.yPx, c.yPx}), maxY = std::max({a.yPx, b.yPx, c.yPx});
    return !(maxX < rx0 || minX > rx1 || maxY < ry0 || minY > ry1);
}

QRect qRect(const PixelRect& r) { return QRect(QPoint(r.x0, r.y0), QPoint(r.x1, r.y1)); }

PixelRect pixelRect(const QRect& r) { return PixelRect{r.left(), r.top(), r.right(), r.bottom()}; }

}  // namespace

SoftwareViewport::SoftwareViewport(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);  // every pixel is painted: Qt need not clear first
    setFocusPolicy(Qt::StrongFocus);
    setContextMenuPolicy(Qt::PreventContextMenu);  // right-drag pans; no menu from the window either
    setMinimumSize(160, 120);
}

QImage SoftwareViewport::grabImage() { return grab().toImage(); }

void SoftwareViewport::sceneChanged(bool) { update(); }

void SoftwareViewport::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    paintAll(painter, size(), float(devicePixelRatioF()));
    countFrame();
}

void SoftwareViewport::paintAll(QPainter& painter, QSize logicalSize, float devicePixelRatio) {
    const QSize sizePx(std::max(1, qRound(logicalSize.width() * devicePixelRatio)),
                       std::max(1, qRound(logicalSize.height() * devicePixelRatio)));
    rasterScene(sizePx, devicePixelRatio);
    mFrame.setDevicePixelRatio(devicePixelRatio);
    painter.drawImage(QPointF(0, 0), mFrame);
    paintExerciseMarkers(painter, mExerciseMarkers, mCamera, logicalSize);
    paintSceneOverlay(painter, mScene, mCamera, logicalSize, mShowRestGhost);
}

void SoftwareViewport::rasterScene(QSize sizePx, float devicePixelRatio) {
    (void)devicePixelRatio;
    const int width = sizePx.width(), height = sizePx.height();
    const glm::vec2 size{float(width), float(height)};
    const glm::mat4 view = mCamera.view();
    const glm::mat4 projection = mCamera.projection(size.x / size.y);
    // Seen from outside a closed surface only front faces are nearest: skip the rest. An outward
    // counter-clockwise triangle facing the eye has a negative area in y-down screen coordinates.
    const int backSign = mBackFaceCulling && mScene.closedAndConsistent() && mScene.outside(mCamera.eyeMm())
                             ? mScene.outwardWinding()
                             : 0;
    const float opacity = surfaceOpacity();
    const FrameKey key{sizePx, view, projection, mWireframe, mShowRestGhost, backSign, opacity};
    // Only the vertices that changed since the last frame (and the corners around them, whose
    // normals moved) are drawn again, inside the rectangle they cover, when nothing else changed.
    // The ghost blends over what is there, so it is always drawn whole.
    const bool whole = mScene.empty() || mScene.allDirty() || mNormals.size() != mScene.vertexCount() ||
                       mFrame.size() != sizePx || !mFrameValid || !(key == mLastKey) || mShowRestGhost;
    mLastKey = key;
    mLastRaster = RasterStats{};
    mLastRaster.whole = whole;
    if (mFrame.size() != sizePx || mFrame.format() != QImage::Format_RGB32)
        mFrame = QImage(sizePx, QImage::Format_RGB32);
    const std::uint32_t background = packRgb(style::kBackground.x, style::kBackground.y, style::kBackground.z);
    auto* pixels = reinterpret_cast<std::uint32_t*>(mFrame.bits());
    const int stride = int(mFrame.bytesPerLine() / 4);
    mFrameValid = !mScene.empty();
    if (mScene.empty()) {
        mFrame.fill(background);
        return;
    }
    if (!whole && mScene.dirtyVertices().empty()) return;  // the same picture as last time

    const FrameCamera camera{view, projection, glm::mat3(view),  // rigid: maps normals too
                             glm::normalize(style::kLightDirView), size};
    auto project = [&](const glm::vec3& pointMm, const glm::vec3& normal) {
        return projectVertex(camera, pointMm, normal);
    };
    const auto positions = mScene.positionsMm();
    const auto indices = mScene.indices();
    PixelRect region{0, 0, width - 1, height - 1};
    if (whole) {
        mScene.computeVertexNormals(mNormals);
        mProjected.resize(positions.size());
        for (std::size_t v = 0; v < positions.size(); ++v) mProjected[v] = project(positions[v], mNormals[v]);
    } else {
        region = pixelRect(reprojectChanged(camera, sizePx));
    }
    mScene.clearDirty();
    if (region.empty()) return;
    mDepth.resize(std::size_t(width) * std::size_t(height));
    for (int y = region.y0; y <= region.y1; ++y) {
        std::fill(pixels + std::ptrdiff_t(y) * stride + region.x0, pixels + std::ptrdiff_t(y) * stride + region.x1 + 1,
                  background);
        std::fill(mDepth.begin() + std::ptrdiff_t(y) * width + region.x0,
                  mDepth.begin() + std::ptrdiff_t(y) * width + region.x1 + 1, 0.0f);
    }
    mLastRaster.regionPx = std::size_t(region.x1 - region.x0 + 1) * std::size_t(region.y1 - region.y0 + 1);

    const auto weights = mScene.pressedWeights();
    const auto rings = mScene.rings();
    auto visible = [&](const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c) {
        return inRegion(region, a, b, c);
    };
    const float wireAlpha = mWireframe ? style::kWireAlpha : 0.0f;
    const glm::vec3 wire = style::kWire;
    for (std::size_t t = 0; 3 * t + 2 < indices.size(); ++t) {
        const std::uint32_t ia = indices[3 * t], ib = indices[3 * t + 1], ic = indices[3 * t + 2];
        const ProjectedVertex &pa = mProjected[ia], &pb = mProjected[ib], &pc = mProjected[ic];
        if (!visible(pa, pb, pc)) continue;
        ++mLastRaster.triangles;
        // The lowest ring among the corners colours the triangle (as the GL geometry shader does);
        // outside the rings the displacement tints it.
        const std::uint8_t ring = std::min({rings[ia], rings[ib], rings[ic]});
        glm::vec3 base;
        float ambient = style::kAmbient;
        if (style::hasRingColour(ring)) {
            base = style::kRingColours[ring];
            ambient = style::kRingAmbient;
        } else {
            base = glm::mix(style::kTissue, style::kPressed, (weights[ia] + weights[ib] + weights[ic]) / 3.0f);
        }
        fillTriangle(corner(pa), corner(pb), corner(pc), region, backSign, wireAlpha > 0.0f,
                     [&](int x, int y, float l0, float l1, float l2, float edgePx, const Corner& a, const Corner& b,
                         const Corner& c) {
                         const float depth = l0 * a.invDepth + l1 * b.invDepth + l2 * c.invDepth;
                         float& stored = mDepth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                         if (depth <= stored) return;
                         stored = depth;
                         const float diffuse = l0 * a.diffuse + l1 * b.diffuse + l2 * c.diffuse;
                         const float specular = l0 * a.specular + l1 * b.specular + l2 * c.specular;
                         glm::vec3 rgb = base * (ambient + (1.0f - ambient) * diffuse) + glm::vec3(specular);
                         if (wireAlpha > 0.0f && edgePx < 1.0f)
                             rgb = glm::mix(rgb, wire, wireAlpha * wireWeight(edgePx));
                         rgb = glm::mix(style::kBackground, rgb, opacity);  // as mesh.frag
                         pixels[std::ptrdiff_t(y) * stride + x] = packRgb(rgb.x, rgb.y, rgb.z);
                     });
    }

    if (mShowRestGhost) drawRestGhost(camera, qRect(region));
}

SoftwareViewport::ProjectedVertex SoftwareViewport::projectVertex(const FrameCamera& camera, const glm::vec3& pointMm,
                                                                  const glm::vec3& normal) {
    const glm::vec4 pv = camera.view * glm::vec4(pointMm, 1.0f);
    const glm::vec4 clip = camera.projection * pv;
    const bool inFront = clip.w > 1e-6f && clip.z > -clip.w;
    const float w = inFront ? clip.w : 1.0f;
    // Two-sided, whatever the winding: open meshes show their inside.
    glm::vec3 n = camera.rotation * normal;
    if (glm::dot(n, -glm::vec3(pv)) < 0.0f) n = -n;
    // The key light and its highlight (as mesh.frag, per vertex): the highlight moving over a
    // dent's walls shows its shape.
    const glm::vec3 toEye = glm::normalize(-glm::vec3(pv));
    const float specular = style::kSpecular *
                           std::pow(std::max(glm::dot(n, glm::normalize(camera.light + toEye)), 0.0f),
                                    style::kShininess);
    return ProjectedVertex{(clip.x / w * 0.5f + 0.5f) * camera.sizePx.x,
                           (0.5f - clip.y / w * 0.5f) * camera.sizePx.y,
                           inFront ? 1.0f / clip.w : 0.0f,
                           std::max(glm::dot(n, camera.light), 0.0f),
                           specular,
                           inFront};
}

QRect SoftwareViewport::reprojectChanged(const FrameCamera& camera, QSize sizePx) {
    const int width = sizePx.width(), height = sizePx.height();
    const auto positions = mScene.positionsMm();
    const auto indices = mScene.indices();
    // The region: where the changed triangles were and are now, plus the wire's pixel.
    mScene.updateVertexNormals(mNormals, mRecomputed);
    float x0 = camera.sizePx.x, y0 = camera.sizePx.y, x1 = -1.0f, y1 = -1.0f;
    auto include = [&](const ProjectedVertex& p) {
        x0 = std::min(x0, p.xPx);
        y0 = std::min(y0, p.yPx);
        x1 = std::max(x1, p.xPx);
        y1 = std::max(y1, p.yPx);
    };
    bool behind = false;
    for (const VertexId w : mRecomputed) {
        include(mProjected[w]);
        behind = behind || !mProjected[w].inFront;
    }
    for (const VertexId w : mRecomputed) mProjected[w] = projectVertex(camera, positions[w], mNormals[w]);
    for (const VertexId w : mRecomputed)
        for (const std::uint32_t t : mScene.vertexTriangles(w))
            for (int k = 0; k < 3; ++k) {
                const ProjectedVertex& p = mProjected[indices[3 * t + std::size_t(k)]];
                include(p);
                behind = behind || !p.inFront;
            }
    if (behind) return qRect(PixelRect{0, 0, width - 1, height - 1});  // a projection across the eye bounds nothing
    return qRect(PixelRect{std::max(0, int(std::floor(x0)) - 2), std::max(0, int(std::floor(y0)) - 2),
                           std::min(width - 1, int(std::ceil(x1)) + 2), std::min(height - 1, int(std::ceil(y1)) + 2)});
}

void SoftwareViewport::drawRestGhost(const FrameCamera& camera, const QRect& rect) {
    const PixelRect region = pixelRect(rect);
    const int width = mFrame.width();
    auto* pixels = reinterpret_cast<std::uint32_t*>(mFrame.bits());
    const int stride = int(mFrame.bytesPerLine() / 4);
    const auto indices = mScene.indices();
    const auto weights = mScene.pressedWeights();
    auto project = [&](const glm::vec3& pointMm, const glm::vec3& normal) {
        return projectVertex(camera, pointMm, normal);
    };
    auto visible = [&](const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c) {
        return inRegion(region, a, b, c);
    };
    // The rest shape of every triangle with a displaced corner, translucent, where it stands in
    // front of the tissue (over a dent); its edges brighter.
    const auto rest = mScene.restPositionsMm();
    const glm::vec3 ghost = style::kGhost;
    for (std::size_t t = 0; 3 * t + 2 < indices.size(); ++t) {
        const std::uint32_t ia = indices[3 * t], ib = indices[3 * t + 1], ic = indices[3 * t + 2];
        if (!(weights[ia] > 0.0f || weights[ib] > 0.0f || weights[ic] > 0.0f)) continue;
        const ProjectedVertex pa = project(rest[ia], mNormals[ia]), pb = project(rest[ib], mNormals[ib]),
                              pc = project(rest[ic], mNormals[ic]);
        if (!visible(pa, pb, pc)) continue;
        fillTriangle(corner(pa), corner(pb), corner(pc), region, 0, true,
                     [&](int x, int y, float l0, float l1, float l2, float edgePx, const Corner& a, const Corner& b,
                         const Corner& c) {
                         const float depth = l0 * a.invDepth + l1 * b.invDepth + l2 * c.invDepth;
                         const float stored = mDepth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                         if (depth <= 0.0f) return;
                         if (stored > 0.0f && 1.0f / depth > 1.0f / stored - kGhostMarginMm) return;
                         const float alpha = edgePx < 1.0f ? style::kGhostWireAlpha : style::kGhostFillAlpha;
                         std::uint32_t& pixel = pixels[std::ptrdiff_t(y) * stride + x];
                         const glm::vec3 under(float((pixel >> 16) & 0xff) / 255.0f,
                                               float((pixel >> 8) & 0xff) / 255.0f, float(pixel & 0xff) / 255.0f);
                         const glm::vec3 rgb = glm::mix(under, ghost, alpha);
                         pixel = packRgb(rgb.x, rgb.y, rgb.z);
                     });
    }
}

void SoftwareViewport::mousePressEvent(QMouseEvent* event) {
    if (handleMousePress(*event)) update();
}

void SoftwareViewport::mouseMoveEvent(QMouseEvent* event) {
    if (handleMouseMove(*event)) update();
}

void SoftwareViewport::mouseReleaseEvent(QMouseEvent* event) {
    if (handleMouseRelease(*event)) update();
}

void SoftwareViewport::wheelEvent(QWheelEvent* event) {
    if (handleWheel(*event)) update();
    event->accept();
}

}  // namespace palpate
