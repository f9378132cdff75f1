#include "app/gui/ViewportBenchmark.h"

#include "app/gui/HapticSession.h"
#include "engine/core/MeshGenerator.h"
#include "widgets/MeshViewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QScreen>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <vector>

namespace palpate {

namespace {

/// Longest wait for the stroke to press before measuring anyway.
constexpr double kMaxWarmUpS = 3.0;
/// Frames drawn before measuring in any case (the first one uploads the whole mesh).
constexpr int kMinWarmUpFrames = 5;

QString glRendererString(QOpenGLWidget* widget) {
    widget->makeCurrent();
    QString text;
    if (QOpenGLContext* context = QOpenGLContext::currentContext()) {
        QOpenGLFunctions* f = context->functions();
        const auto* renderer = reinterpret_cast<const char*>(f->glGetString(GL_RENDERER));
        const auto* version = reinterpret_cast<const char*>(f->glGetString(GL_VERSION));
        text = QStringLiteral("%1, %2").arg(QLatin1String(renderer ? renderer : "?"), QLatin1String(version ? version : "?"));
    }
    widget->doneCurrent();
    return text;
}

}  // namespace

int runViewportBenchmark(const QString& secondsText, bool softwareRender) {
    bool ok = false;
    const double seconds = secondsText.toDouble(&ok);
    if (!ok || !(seconds > 0.0) || !std::isfinite(seconds)) {
        std::fprintf(stderr, "palpate: --seconds needs a number > 0, not '%s'\n", qPrintable(secondsText));
        return 2;
    }
    ViewportBenchmarkDef options;
    options.seconds = seconds;
    options.renderer = softwareRender ? RendererChoice::Software : RendererChoice::Auto;
    return runViewportBenchmark(options);
}

int runViewportBenchmark(const ViewportBenchmarkDef& options) {
    // As fast as it goes: no vertical sync (where the platform honours it) for the window's swaps.
    QSurfaceFormat defaultFormat = QSurfaceFormat::defaultFormat();
    defaultFormat.setSwapInterval(0);
    QSurfaceFormat::setDefaultFormat(defaultFormat);

    // The sphere goes through a file so that the session loads it like any mesh (validation,
    // Morton order, the scene and a sim:stroke device aimed at it, the loop thread).
    auto generated = generateMesh(GeneratedShape::Sphere, options.vertexCount);
    if (!generated.mesh) {
        std::fprintf(stderr, "palpate: the %zu-vertex sphere could not be generated\n", options.vertexCount);
        return 1;
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("sphere_%1.off").arg(options.vertexCount));
    if (!dir.isValid()) {
        std::fprintf(stderr, "palpate: no temporary directory for the benchmark mesh\n");
        return 1;
    }
    if (const std::string error = generated.mesh->save(path.toStdString()); !error.empty()) {
        std::fprintf(stderr, "palpate: %s\n", error.c_str());
        return 1;
    }
    generated.mesh.reset();

    HapticSession session(LoopMode::Threaded);
    if (const std::string error = session.loadMesh(path.toStdString()); !error.empty()) {
        std::fprintf(stderr, "palpate: %s\n", error.c_str());
        return 1;
    }
    const TissueMesh& mesh = *session.drawnMesh();

    QString reason;
    std::unique_ptr<QWidget> owner;  // the viewport's widget, top level
    Viewport* viewport = createViewport(options.renderer, nullptr, &reason);
    QWidget* widget = viewport->widget();
    owner.reset(widget);
    widget->setWindowTitle(QStringLiteral("Palpate viewport benchmark"));
    viewport->setMesh(mesh);
    // Maximised; without a window manager (Xvfb) showMaximized alone may not resize.
    if (QScreen* screen = QGuiApplication::primaryScreen()) widget->setGeometry(screen->availableGeometry());
    widget->showMaximized();

    auto* glWidget = qobject_cast<QOpenGLWidget*>(widget);
    auto* meshViewport = dynamic_cast<MeshViewport*>(viewport);

    QElapsedTimer clock;
    clock.start();
    bool measuring = false;
    int warmUpFrames = 0;
    double measureStartS = 0.0, lastFrameS = 0.0;
    std::vector<double> frameMs;
    frameMs.reserve(std::size_t(options.seconds * 2000.0) + 16);
    std::size_t contactFrames = 0, fullUploads = 0, partialUploads = 0, uploadedVertices = 0, uploadRanges = 0;
    bool finished = false;

    auto finish = [&] {
        if (finished) return;
        finished = true;
        QApplication::exit(0);
    };
    auto nextSnapshot = [&] {
        if (session.observe() != HapticSession::Observation::Nothing) viewport->setSnapshot(session.view());
        session.collectRetired();
    };
    // Called when a frame has been finished (swapped, or painted in software).
    auto frameDone = [&] {
        if (finished) return;
        const double nowS = double(clock.nsecsElapsed()) * 1e-9;
        if (!measuring) {
            ++warmUpFrames;
            if (warmUpFrames >= kMinWarmUpFrames && (session.observed().contact || nowS > kMaxWarmUpS)) {
                measuring = true;
                measureStartS = nowS;
            }
        } else {
            frameMs.push_back((nowS - lastFrameS) * 1e3);
            if (session.view().contact) ++contactFrames;
            if (meshViewport) {
                const auto& upload = meshViewport->lastUpload();
                (upload.full ? fullUploads : partialUploads) += 1;
                uploadedVertices += upload.vertices;
                uploadRanges += upload.ranges;
            }
            if (nowS - measureStartS >= options.seconds) {
                lastFrameS = nowS;
                finish();
                return;
            }
        }
        lastFrameS = nowS;
        nextSnapshot();
    };

    QTimer softwareTimer;
    if (glWidget) {
        QObject::connect(glWidget, &QOpenGLWidget::frameSwapped, glWidget, [&] {
            frameDone();
            if (!finished) glWidget->update();  // the next frame at once
        });
        glWidget->update();
    } else {
        softwareTimer.setInterval(0);
        QObject::connect(&softwareTimer, &QTimer::timeout, widget, [&] {
            nextSnapshot();
            widget->repaint();  // paints now
            frameDone();
        });
        softwareTimer.start();
    }
    // Should frames stop coming (a window that is never exposed), give up rather than hang.
    const int watchdogMs = int((options.seconds + kMaxWarmUpS + 30.0) * 1000.0);
    bool timedOut = false;
    QTimer::singleShot(watchdogMs, widget, [&] {
        timedOut = !finished;
        finish();
    });

    std::printf("viewport benchmark: generated sphere, %zu vertices, %zu triangles; %s renderer (%s)\n",
                mesh.vertexCount(), mesh.triangleCount(), qPrintable(rendererName(viewport->kind())), qPrintable(reason));
    std::fflush(stdout);
    QApplication::exec();
    softwareTimer.stop();
    const QString glInfo = glWidget ? glRendererString(glWidget) : QString();
    const QSize sizePx = widget->size() * widget->devicePixelRatioF();
    const RendererKind kind = viewport->kind();
    session.stop();
    const double loopRateHz = session.observed().counters.achievedRateHz;
    owner.reset();  // the viewport goes with its widget
    viewport = nullptr;
    meshViewport = nullptr;
    glWidget = nullptr;

    if (timedOut || frameMs.empty()) {
        std::fprintf(stderr, "palpate: the viewport drew %zu frames in the benchmark (was the window shown?)\n", frameMs.size());
        return 1;
    }
    const double elapsedS = lastFrameS - measureStartS;
    const double meanMs = std::accumulate(frameMs.begin(), frameMs.end(), 0.0) / double(frameMs.size());
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    const double p95Ms = sorted[std::min(sorted.size() - 1, std::size_t(std::ceil(0.95 * double(sorted.size()))) - 1)];
    const double fps = elapsedS > 0.0 ? double(frameMs.size()) / elapsedS : 0.0;
    const std::size_t frames = frameMs.size();

    std::printf("window %dx%d px%s%s; measured %.2f s from %s; haptic loop %.0f Hz\n", sizePx.width(), sizePx.height(),
                glInfo.isEmpty() ? "" : ", GL: ", qPrintable(glInfo), elapsedS,
                contactFrames > 0 ? "the stroke's contact" : "the warm-up", loopRateHz);
    std::printf("frames=%zu mean_frame_ms=%.2f p95_frame_ms=%.2f fps=%.1f renderer=%s\n", frames, meanMs, p95Ms, fps,
                qPrintable(rendererName(kind)));
    std::printf("contact in %zu of %zu frames", contactFrames, frames);
    if (kind == RendererKind::OpenGL) {
        const double perFrame = double(uploadedVertices) / double(frames);
        std::printf("; uploads: %zu partial, %zu full, mean %.0f vertices (%.1f kB, %.1f ranges) per frame of %zu",
                    partialUploads, fullUploads, perFrame, perFrame * 32.0 / 1024.0, double(uploadRanges) / double(frames),
                    mesh.vertexCount());
    }
    std::printf("\n");
    std::fflush(stdout);
    return 0;
}

}  // namespace palpate
