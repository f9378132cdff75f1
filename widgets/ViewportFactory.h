#pragma once
// Picks the renderer: OpenGL where a 3.3 core context can really be made current on a GPU, the
// software one otherwise. Qt's offscreen platform is always software: on Debian's Qt 6.4 it has no
// OpenGL, and QOpenGLWidget::grabFramebuffer crashes there (docs/architecture.md). Where OpenGL is
// itself a CPU rasteriser (Mesa's llvmpipe or softpipe) the software viewport is several times
// faster and is picked; forced there, the OpenGL viewport draws without multisampling, which such
// a rasteriser pays for in full (docs/bench/README.md, "Viewport").

#include "widgets/Viewport.h"

#include <QString>

class QWidget;

namespace palpate {

enum class RendererChoice {
    Auto,      ///< OpenGL when available on a GPU, else software
    Software,  ///< always software (--software-render)
    OpenGL,    ///< OpenGL whenever available, even as a CPU rasteriser (--opengl-render)
};

/// What openGl33Available found out.
struct GlProbe {
    bool available = false;
    QString whyNot;    ///< when not available: what failed
    QString renderer;  ///< GL_RENDERER of the context, when one was made current
};

/// Whether an OpenGL 3.3 core context can be created and made current here. Needs a QGuiApplication.
GlProbe probeOpenGl33();
/// The same, as a yes/no; on false `whyNot` (if given) says what failed.
bool openGl33Available(QString* whyNot = nullptr);

/// Whether GL_RENDERER names a rasteriser that runs on the CPU (llvmpipe, softpipe, swrast, the
/// "Software Rasterizer" of other drivers): every pixel and sample is paid for by the CPU.
bool isSoftwareGlRenderer(const QString& glRenderer);

/// The multisampling the OpenGL viewport asks for on `glRenderer`: none on a software
/// rasteriser (4x costs it up to four times the fragment work), 4x elsewhere.
/// `overrideSamples` (>= 0) wins: the benchmark's baseline with the old 4x.
int viewportSamplesFor(const QString& glRenderer, int overrideSamples = -1);

/// PALPATE_GL_SAMPLES when set to a whole number >= 0 (benchmarks), else -1.
int samplesOverrideFromEnvironment();

/// The renderer for `choice` given what the probe found, and why (the status bar's words).
/// A pure function of its arguments: tested with GL_RENDERER strings.
struct RendererDecision {
    RendererKind kind = RendererKind::Software;
    int samples = 0;  ///< multisampling for the OpenGL viewport
    QString reason;
};
RendererDecision decideRenderer(RendererChoice choice, const GlProbe& probe, int overrideSamples = -1);

/// Creates the viewport widget as a child of `parent`. `reason` (if given) says why this renderer.
Viewport* createViewport(RendererChoice choice, QWidget* parent, QString* reason = nullptr);

}  // namespace palpate
