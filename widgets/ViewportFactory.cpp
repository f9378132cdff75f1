#include "widgets/ViewportFactory.h"

#include "widgets/MeshViewport.h"
#include "widgets/SoftwareViewport.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSurfaceFormat>

namespace palpate {

bool openGl33Available(QString* whyNot) {
    auto fail = [whyNot](const QString& why) {
        if (whyNot) *whyNot = why;
        return false;
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
    context.doneCurrent();
    return true;
}

Viewport* createViewport(RendererChoice choice, QWidget* parent, QString* reason) {
    QString why;
    if (choice == RendererChoice::Software) {
        why = QStringLiteral("software rendering was requested");
    } else if (openGl33Available(&why)) {
        if (reason) *reason = QStringLiteral("OpenGL 3.3 core is available");
        return new MeshViewport(parent);
    }
    if (reason) *reason = why;
    return new SoftwareViewport(parent);
}

}  // namespace palpate
