#pragma once
// Pixel checks shared by the viewport tests: colours are recognised by chromaticity, the share of
// each channel in the sum, which shading (a grey factor) and the black wire blend leave unchanged.

#include <QImage>
#include <QRect>
#include <QRectF>

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdlib>

namespace palpate::test {

/// Whether `pixel` is `colour` scaled by some brightness: chromaticity (r, g shares) within
/// `tolerance`, and bright enough (channel sum >= minSum of 765) for the shares to mean something.
inline bool sameChromaticity(QRgb pixel, const glm::vec3& colour, float tolerance = 0.03f, int minSum = 90) {
    const int sum = qRed(pixel) + qGreen(pixel) + qBlue(pixel);
    if (sum < minSum) return false;
    const float colourSum = colour.x + colour.y + colour.z;
    const float dr = float(qRed(pixel)) / float(sum) - colour.x / colourSum;
    const float dg = float(qGreen(pixel)) / float(sum) - colour.y / colourSum;
    return std::abs(dr) <= tolerance && std::abs(dg) <= tolerance;
}

/// Pixels of `colour` (by chromaticity) outside `exclude`.
inline int countChromaticity(const QImage& image, const glm::vec3& colour, const QRectF& exclude = {},
                             float tolerance = 0.03f) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (!exclude.contains(QPointF(x + 0.5, y + 0.5)) && sameChromaticity(image.pixel(x, y), colour, tolerance))
                ++count;
    return count;
}

inline bool nearRgb(QRgb pixel, QRgb other, int tolerance) {
    return std::abs(qRed(pixel) - qRed(other)) <= tolerance && std::abs(qGreen(pixel) - qGreen(other)) <= tolerance &&
           std::abs(qBlue(pixel) - qBlue(other)) <= tolerance;
}

/// Pixels farther than `tolerance` (per channel) from `background`.
inline int countNotNear(const QImage& image, QRgb background, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (!nearRgb(image.pixel(x, y), background, tolerance)) ++count;
    return count;
}

/// Pixels that differ by more than `tolerance` in some channel, outside `exclude`; the images
/// must have the same size.
inline int countDifferent(const QImage& a, const QImage& b, int tolerance, const QRectF& exclude = {}) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (!exclude.contains(QPointF(x + 0.5, y + 0.5)) && !nearRgb(a.pixel(x, y), b.pixel(x, y), tolerance))
                ++count;
    return count;
}

/// Of the surface's pixels in `plain` (not `background`, outside `exclude`), how many `faded` shows
/// as that pixel mixed with the background at `opacity` (within `tolerance` per channel).
struct FadedCount {
    int surface = 0;
    int faded = 0;
};
inline FadedCount countFaded(const QImage& plain, const QImage& faded, QRgb background, float opacity,
                             const QRectF& exclude, int tolerance) {
    FadedCount c;
    auto mix = [&](int bg, int v) { return int(std::lround(bg + (v - bg) * opacity)); };
    for (int y = 0; y < plain.height(); ++y)
        for (int x = 0; x < plain.width(); ++x) {
            const QRgb p = plain.pixel(x, y);
            if (exclude.contains(QPointF(x + 0.5, y + 0.5)) || nearRgb(p, background, 12)) continue;
            ++c.surface;
            const QRgb expected = qRgb(mix(qRed(background), qRed(p)), mix(qGreen(background), qGreen(p)),
                                       mix(qBlue(background), qBlue(p)));
            if (nearRgb(faded.pixel(x, y), expected, tolerance)) ++c.faded;
        }
    return c;
}

}  // namespace palpate::test
