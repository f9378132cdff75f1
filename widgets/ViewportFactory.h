#pragma once
// Picks the renderer: OpenGL where a 3.3 core context can really be made current, QPainter otherwise.
// Qt's offscreen platform is always software: on Debian's Qt 6.4 it has no OpenGL, and
// QOpenGLWidget::grabFramebuffer crashes there (docs/architecture.md).

#include "widgets/Viewport.h"

#include <QString>

class QWidget;

namespace palpate {

enum class RendererChoice {
    Auto,      ///< OpenGL when available, else software
    Software,  ///< always software (--software-render)
};

/// Whether an OpenGL 3.3 core context can be created and made current here. Needs a QGuiApplication.
/// On false, `whyNot` (if given) says what failed.
bool openGl33Available(QString* whyNot = nullptr);

/// Creates the viewport widget as a child of `parent`. `reason` (if given) says why this renderer.
Viewport* createViewport(RendererChoice choice, QWidget* parent, QString* reason = nullptr);

}  // namespace palpate
