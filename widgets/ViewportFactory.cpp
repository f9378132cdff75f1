#include "widgets/ViewportFactory.h"

#include "widgets/MeshViewport.h"
#include "widgets/SoftwareViewport.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>

namespace palpate {

namespace {
constexpr int kHardwareSamples = 4;
}

GlProbe probeOpenGl33() {
    GlProbe probe;
    auto fail = [&probe](const QString& why) {
        probe.whyNot = why;
        return probe;
    };
    const QString platform = QGuiApplication::platformName();
    // These platforms may still hand out a context (GLX when DISPLAY is set), but widgets cannot use it.
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
        return fail(QStringLiteral("the '%1' Qt platform has no OpenGL for widgets").arg(platform));

    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOpenGLContext context;
    context.setFormat(format);
    if (!context.create()) return fail(QStringLiteral("no OpenGL context could be created"));
    const QSurfaceFormat got = context.format();
    if (got.version() < qMakePair(3, 3))
        return fail(QStringLiteral("OpenGL %1.%2 is older than 3.3").arg(got.majorVersion()).arg(got.minorVersion()));
    // Creating is not enough: some drivers hand out a context that cannot be made current.
    QOffscreenSurface surface;
    surface.setFormat(got);
    surface.create();
    if (!surface.isValid()) return fail(QStringLiteral("no offscreen surface for OpenGL"));
    if (!context.makeCurrent(&surface)) return fail(QStringLiteral("the OpenGL context cannot be made current"));
    const auto* renderer = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    probe.renderer = QString::fromLatin1(renderer ? renderer : "");
    context.doneCurrent();
    probe.available = true;
    return probe;
}

bool openGl33Available(QString* whyNot) {
    const GlProbe probe = probeOpenGl33();
    if (!probe.available && whyNot) *whyNot = probe.whyNot;
    return probe.available;
}

bool isSoftwareGlRenderer(const QString& glRenderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "software rasterizer"})
        if (glRenderer.contains(QLatin1String(name), Qt::CaseInsensitive)) return true;
    return false;
}

int viewportSamplesFor(const QString& glRenderer, int overrideSamples) {
    if (overrideSamples >= 0) return overrideSamples;
    return isSoftwareGlRenderer(glRenderer) ? 0 : kHardwareSamples;
}

int samplesOverrideFromEnvironment() {
    bool ok = false;
    const int samples = qEnvironmentVariableIntValue("PALPATE_GL_SAMPLES", &ok);
    return ok && samples >= 0 ? samples : -1;
}

RendererDecision decideRenderer(RendererChoice choice, const GlProbe& probe, int overrideSamples) {
    RendererDecision decision;
    if (choice == RendererChoice::Software) {
        decision.reason = QStringLiteral("software rendering was requested");
        return decision;
    }
    if (!probe.available) {
        decision.reason = probe.whyNot;
        return decision;
    }
    const QString renderer = probe.renderer.isEmpty() ? QStringLiteral("unknown renderer") : probe.renderer;
    if (choice == RendererChoice::Auto && isSoftwareGlRenderer(probe.renderer)) {
        decision.reason = QStringLiteral("OpenGL here is %1, a CPU rasteriser: the software renderer is faster")
                              .arg(renderer);
        return decision;
    }
    decision.kind = RendererKind::OpenGL;
    decision.samples = viewportSamplesFor(probe.renderer, overrideSamples);
    decision.reason = QStringLiteral("OpenGL 3.3 core is available (%1; %2)")
                          .arg(renderer, decision.samples > 0
                                             ? QStringLiteral("%1x multisampling").arg(decision.samples)
                                             : QStringLiteral("no multisampling"));
    return decision;
}

Viewport* createViewport(RendererChoice choice, QWidget* parent, QString* reason) {
    const GlProbe probe = choice == RendererChoice::Software ? GlProbe{} : probeOpenGl33();
    const RendererDecision decision = decideRenderer(choice, probe, samplesOverrideFromEnvironment());
    if (reason) *reason = decision.reason;
    if (decision.kind == RendererKind::OpenGL) return new MeshViewport(decision.samples, parent);
    return new SoftwareViewport(parent);
}

}  // namespace palpate
