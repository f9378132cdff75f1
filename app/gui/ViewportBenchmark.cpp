#include "app/gui/ViewportBenchmark.h"

#include "app/gui/MainWindow.h"
#include "engine/core/MeshGenerator.h"
#include "widgets/MeshViewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QTemporaryDir>
#include <QTimer>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <vector>

namespace palpate {

namespace {

/// The interactive window's size (app/gui/main.cpp): what a user sees at start.
constexpr int kWindowWidthPx = 1280;
constexpr int kWindowHeightPx = 860;
/// Longest wait for the device to touch the tissue before giving up.
constexpr double kMaxWaitForContactS = 10.0;
/// After the first contact: the dent forms and the first whole upload is behind us.
constexpr double kSettleS = 0.5;

QString glRendererString(QOpenGLWidget* widget) {
    widget->makeCurrent();
    QString text;
    if (QOpenGLContext* context = QOpenGLContext::currentContext()) {
        QOpenGLFunctions* f = context->functions();
        const auto* renderer = reinterpret_cast<const char*>(f->glGetString(GL_RENDERER));
        const auto* version = reinterpret_cast<const char*>(f->glGetString(GL_VERSION));
        text = QStringLiteral("%1, %2").arg(QLatin1String(renderer ? renderer : "?"),
                                            QLatin1String(version ? version : "?"));
    }
    widget->doneCurrent();
    return text;
}

/// The machine's 1-minute load average (other processes compete for the cores), or -1.
double loadAverage() {
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly)) return -1.0;
    bool ok = false;
    const double load = QString::fromLatin1(file.readLine()).section(QLatin1Char(' '), 0, 0).toDouble(&ok);
    return ok ? load : -1.0;
}

/// CPU seconds this (the GUI) thread has used: with other work on the machine, the wall-clock frame
/// time grows, this much less.
double threadCpuS() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

/// Calls `painted` after each paint event of the watched widget.
class PaintWatcher final : public QObject {
public:
    explicit PaintWatcher(std::function<void()> painted) : mPainted(std::move(painted)) {}
    bool eventFilter(QObject*, QEvent* event) override {
        if (event->type() == QEvent::Paint) mPainted();
        return false;
    }

private:
    std::function<void()> mPainted;
};

}  // namespace

int runViewportBenchmark(const QString& secondsText, const QString& meshPath, RendererChoice renderer) {
    bool ok = false;
    const double seconds = secondsText.toDouble(&ok);
    if (!ok || !(seconds > 0.0) || !std::isfinite(seconds)) {
        std::fprintf(stderr, "palpate: --seconds needs a number > 0, not '%s'\n", qPrintable(secondsText));
        return 2;
    }
    ViewportBenchmarkDef options;
    options.seconds = seconds;
    options.meshPath = meshPath;
    options.renderer = renderer;
    return runViewportBenchmark(options);
}

int runViewportBenchmark(const ViewportBenchmarkDef& options) {
    // As fast as it goes: no vertical sync (where the platform honours it) for the window's swaps.
    QSurfaceFormat defaultFormat = QSurfaceFormat::defaultFormat();
    defaultFormat.setSwapInterval(0);
    QSurfaceFormat::setDefaultFormat(defaultFormat);

    QTemporaryDir dir;
    QString path = options.meshPath;
    if (path.isEmpty()) {
        // The sphere goes through a file so that the window loads it like any mesh.
        auto generated = generateMesh(GeneratedShape::Sphere, options.vertexCount);
        if (!generated.mesh) {
            std::fprintf(stderr, "palpate: the %zu-vertex sphere could not be generated\n", options.vertexCount);
            return 1;
        }
        if (!dir.isValid()) {
            std::fprintf(stderr, "palpate: no temporary directory for the benchmark mesh\n");
            return 1;
        }
        path = dir.filePath(QStringLiteral("sphere_%1.off").arg(options.vertexCount));
        if (const std::string error = generated.mesh->save(path.toStdString()); !error.empty()) {
            std::fprintf(stderr, "palpate: %s\n", error.c_str());
            return 1;
        }
    }

    MainWindow window(options.renderer, LoopMode::Threaded);
    if (const QString error = window.setDeviceUri(options.deviceUri); !error.isEmpty()) {
        std::fprintf(stderr, "palpate: %s\n", qPrintable(error));
        return 1;
    }
    if (const QString error = window.loadMesh(path); !error.isEmpty()) {
        std::fprintf(stderr, "palpate: %s\n", qPrintable(error));
        return 1;
    }
    Viewport* viewport = window.viewport();
    const auto mesh = window.session().drawnMesh();
    const std::size_t vertexCount = mesh ? mesh->vertexCount() : 0, triangleCount = mesh ? mesh->triangleCount() : 0;
    window.resize(kWindowWidthPx, kWindowHeightPx);
    window.show();

    auto* glWidget = qobject_cast<QOpenGLWidget*>(viewport->widget());
    auto* meshViewport = dynamic_cast<MeshViewport*>(viewport);

    QElapsedTimer clock;
    clock.start();
    enum class Phase { WaitingForContact, Settling, Measuring, Done } phase = Phase::WaitingForContact;
    double contactAtS = 0.0, measureStartS = 0.0, lastPaintS = 0.0, measureEndS = 0.0;
    std::uint64_t framesAtStart = 0, framesAtEnd = 0;
    double cpuAtStartS = 0.0, cpuAtEndS = 0.0;
    std::vector<double> frameMs;
    frameMs.reserve(std::size_t(options.seconds * 1000.0) + 16);
    std::size_t paints = 0, contactPaints = 0, fullUploads = 0, partialUploads = 0, uploadedVertices = 0,
                uploadRanges = 0;
    bool failed = false;

    auto finish = [&](bool failure) {
        if (phase == Phase::Done) return;
        failed = failure;
        phase = Phase::Done;
        QApplication::exit(0);
    };
    // A paint of the viewport has just finished (its event filter runs before the paint, so the
    // interval between two calls is a frame either way).
    PaintWatcher watcher([&] {
        if (phase != Phase::Measuring) return;
        const double nowS = double(clock.nsecsElapsed()) * 1e-9;
        if (paints > 0) frameMs.push_back((nowS - lastPaintS) * 1e3);
        lastPaintS = nowS;
        ++paints;
        if (window.session().view().contact) ++contactPaints;
        if (meshViewport) {
            const auto& upload = meshViewport->lastUpload();
            (upload.full ? fullUploads : partialUploads) += 1;
            uploadedVertices += upload.vertices;
            uploadRanges += upload.ranges;
        }
    });
    viewport->widget()->installEventFilter(&watcher);

    QTimer poll;
    poll.setInterval(20);
    QObject::connect(&poll, &QTimer::timeout, &window, [&] {
        const double nowS = double(clock.nsecsElapsed()) * 1e-9;
        switch (phase) {
            case Phase::WaitingForContact:
                if (window.session().view().contact) {
                    phase = Phase::Settling;
                    contactAtS = nowS;
                } else if (nowS > kMaxWaitForContactS) {
                    std::fprintf(stderr, "palpate: %s did not touch the mesh within %.0f s\n",
                                 qPrintable(options.deviceUri), kMaxWaitForContactS);
                    finish(true);
                }
                break;
            case Phase::Settling:
                if (nowS - contactAtS >= kSettleS) {
                    phase = Phase::Measuring;
                    measureStartS = nowS;
                    framesAtStart = viewport->framesDrawn();
                    cpuAtStartS = threadCpuS();
                }
                break;
            case Phase::Measuring:
                if (nowS - measureStartS >= options.seconds) {
                    measureEndS = nowS;
                    framesAtEnd = viewport->framesDrawn();
                    cpuAtEndS = threadCpuS();
                    finish(false);
                }
                break;
            case Phase::Done: break;
        }
    });
    poll.start();
    // Should nothing happen (a window that is never exposed), give up rather than hang.
    QTimer::singleShot(int((options.seconds + kMaxWaitForContactS + kSettleS + 30.0) * 1000.0), &window,
                       [&] { finish(true); });

    std::printf("viewport benchmark: %s, %zu vertices, %zu triangles; device %s; %s renderer (%s); load %.2f\n",
                qPrintable(QFileInfo(path).fileName()), vertexCount, triangleCount, qPrintable(options.deviceUri),
                qPrintable(rendererName(viewport->kind())), qPrintable(window.rendererReason()), loadAverage());
    std::fflush(stdout);
    QApplication::exec();
    poll.stop();
    viewport->widget()->removeEventFilter(&watcher);
    const QString glInfo = glWidget ? glRendererString(glWidget) : QString();
    const QSize sizePx = viewport->widget()->size() * viewport->widget()->devicePixelRatioF();
    const RendererKind kind = viewport->kind();
    const int samples = meshViewport ? meshViewport->requestedSamples() : 0;
    const double loopRateHz = window.hapticRateHz();
    const double loadAtEnd = loadAverage();
    window.close();  // stops the haptic thread

    const std::uint64_t frames = framesAtEnd - framesAtStart;
    const double elapsedS = measureEndS - measureStartS;
    if (failed || frames == 0 || frameMs.empty() || !(elapsedS > 0.0)) {
        std::fprintf(stderr, "palpate: the viewport drew %llu frames in the benchmark (was the window shown?)\n",
                     static_cast<unsigned long long>(frames));
        return 1;
    }
    const double meanMs = std::accumulate(frameMs.begin(), frameMs.end(), 0.0) / double(frameMs.size());
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    const double p95Ms = sorted[std::min(sorted.size() - 1, std::size_t(std::ceil(0.95 * double(sorted.size()))) - 1)];
    const double fps = double(frames) / elapsedS;

    std::printf("viewport %dx%d px%s%s; measured %.2f s in contact; haptic loop %.0f Hz\n", sizePx.width(),
                sizePx.height(), glInfo.isEmpty() ? "" : ", GL: ", qPrintable(glInfo), elapsedS, loopRateHz);
    const double guiCpuMsPerFrame = (cpuAtEndS - cpuAtStartS) * 1e3 / double(frames);
    std::printf(
        "frames=%llu mean_frame_ms=%.2f p95_frame_ms=%.2f fps=%.1f gui_cpu_ms_per_frame=%.2f renderer=%s "
        "samples=%d vertices=%zu load=%.2f\n",
        static_cast<unsigned long long>(frames), meanMs, p95Ms, fps, guiCpuMsPerFrame, qPrintable(rendererName(kind)),
        samples, vertexCount, loadAtEnd);
    std::printf("contact in %zu of %zu frames", contactPaints, paints);
    if (kind == RendererKind::OpenGL && paints > 0) {
        const double perFrame = double(uploadedVertices) / double(paints);
        std::printf("; uploads: %zu partial, %zu full, mean %.0f vertices (%.1f kB, %.1f ranges) per frame of %zu",
                    partialUploads, fullUploads, perFrame, perFrame * 32.0 / 1024.0,
                    double(uploadRanges) / double(paints), vertexCount);
    }
    std::printf("\n");
    std::fflush(stdout);
    return 0;
}

}  // namespace palpate
