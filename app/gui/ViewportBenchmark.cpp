#include "app/gui/ViewportBenchmark.h"

#include "app/gui/MainWindow.h"
#include "engine/core/MeshGenerator.h"
#include "widgets/ExerciseMarkers.h"
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

/// The generated sphere of `vertexCount` vertices, written into `dir` so that the window loads it
/// like any mesh: its path, or "" (said on stderr).
QString writeSphere(std::size_t vertexCount, const QTemporaryDir& dir) {
    auto generated = generateMesh(GeneratedShape::Sphere, vertexCount);
    if (!generated.mesh) {
        std::fprintf(stderr, "palpate: the %zu-vertex sphere could not be generated\n", vertexCount);
        return {};
    }
    if (!dir.isValid()) {
        std::fprintf(stderr, "palpate: no temporary directory for the benchmark mesh\n");
        return {};
    }
    const QString path = dir.filePath(QStringLiteral("sphere_%1.off").arg(vertexCount));
    if (const std::string error = generated.mesh->save(path.toStdString()); !error.empty()) {
        std::fprintf(stderr, "palpate: %s\n", error.c_str());
        return {};
    }
    return path;
}

/// What the paints and the clocks said while the device pressed.
struct FrameMeasurement {
    double measureStartS = 0.0, measureEndS = 0.0;
    std::uint64_t framesAtStart = 0, framesAtEnd = 0;
    double cpuAtStartS = 0.0, cpuAtEndS = 0.0;
    std::vector<double> frameMs;  ///< between two paints
    std::size_t paints = 0, contactPaints = 0, fullUploads = 0, partialUploads = 0, uploadedVertices = 0,
                uploadRanges = 0;
};

/// The viewport and the machine the frames were measured on (read before the window closes).
struct ViewportFacts {
    QString glInfo;  ///< GL_RENDERER and GL_VERSION; empty for the software renderer
    QSize sizePx;
    RendererKind kind = RendererKind::Software;
    int samples = 0;
    double loopRateHz = 0.0;
    double loadAtEnd = -1.0;
    std::size_t heatPoints = 0;
    std::size_t vertexCount = 0;
};

/// Prints the figures (fps= and the frame times). The exit code: 1 when nothing was measured.
int printResult(const FrameMeasurement& m, const ViewportFacts& facts, bool failed) {
    const std::uint64_t frames = m.framesAtEnd - m.framesAtStart;
    const double elapsedS = m.measureEndS - m.measureStartS;
    if (failed || frames == 0 || m.frameMs.empty() || !(elapsedS > 0.0)) {
        std::fprintf(stderr, "palpate: the viewport drew %llu frames in the benchmark (was the window shown?)\n",
                     static_cast<unsigned long long>(frames));
        return 1;
    }
    const double meanMs = std::accumulate(m.frameMs.begin(), m.frameMs.end(), 0.0) / double(m.frameMs.size());
    std::vector<double> sorted = m.frameMs;
    std::sort(sorted.begin(), sorted.end());
    const double p95Ms = sorted[std::min(sorted.size() - 1, std::size_t(std::ceil(0.95 * double(sorted.size()))) - 1)];
    const double fps = double(frames) / elapsedS;

    std::printf("viewport %dx%d px%s%s; measured %.2f s in contact; haptic loop %.0f Hz\n", facts.sizePx.width(),
                facts.sizePx.height(), facts.glInfo.isEmpty() ? "" : ", GL: ", qPrintable(facts.glInfo), elapsedS,
                facts.loopRateHz);
    const double guiCpuMsPerFrame = (m.cpuAtEndS - m.cpuAtStartS) * 1e3 / double(frames);
    std::printf(
        "frames=%llu mean_frame_ms=%.2f p95_frame_ms=%.2f fps=%.1f gui_cpu_ms_per_frame=%.2f renderer=%s "
        "samples=%d vertices=%zu heat_points=%zu load=%.2f\n",
        static_cast<unsigned long long>(frames), meanMs, p95Ms, fps, guiCpuMsPerFrame,
        qPrintable(rendererName(facts.kind)), facts.samples, facts.vertexCount, facts.heatPoints, facts.loadAtEnd);
    std::printf("contact in %zu of %zu frames", m.contactPaints, m.paints);
    if (facts.kind == RendererKind::OpenGL && m.paints > 0) {
        const double perFrame = double(m.uploadedVertices) / double(m.paints);
        std::printf("; uploads: %zu partial, %zu full, mean %.0f vertices (%.1f kB, %.1f ranges) per frame of %zu",
                    m.partialUploads, m.fullUploads, perFrame, perFrame * 32.0 / 1024.0,
                    double(m.uploadRanges) / double(m.paints), facts.vertexCount);
    }
    std::printf("\n");
    std::fflush(stdout);
    return 0;
}

/// A heat map over every vertex, its forces spread over the scale (as after a thorough examination).
ExerciseMarkers wholeSurfaceHeat(const TissueMesh& mesh) {
    ExerciseMarkers markers;
    markers.heatMinN = 0.4;
    markers.heatMaxN = 4.0;
    const auto& rest = mesh.restPositionsMm();
    const auto& normals = mesh.restNormals();
    for (std::size_t v = 0; v < rest.size(); ++v)
        markers.heat.push_back({rest[v], normals[v], float(0.4 + 3.6 * double(v % 97) / 96.0)});
    return markers;
}

}  // namespace

int runViewportBenchmark(const QString& secondsText, const QString& meshPath, RendererChoice renderer, bool heatMap) {
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
    options.heatMap = heatMap;
    return runViewportBenchmark(options);
}

int runViewportBenchmark(const ViewportBenchmarkDef& options) {
    // As fast as it goes: no vertical sync (where the platform honours it) for the window's swaps.
    QSurfaceFormat defaultFormat = QSurfaceFormat::defaultFormat();
    defaultFormat.setSwapInterval(0);
    QSurfaceFormat::setDefaultFormat(defaultFormat);

    QTemporaryDir dir;
    const QString path = options.meshPath.isEmpty() ? writeSphere(options.vertexCount, dir) : options.meshPath;
    if (path.isEmpty()) return 1;

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
    double contactAtS = 0.0, lastPaintS = 0.0;
    FrameMeasurement m;
    m.frameMs.reserve(std::size_t(options.seconds * 1000.0) + 16);
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
        if (m.paints > 0) m.frameMs.push_back((nowS - lastPaintS) * 1e3);
        lastPaintS = nowS;
        ++m.paints;
        if (window.session().view().contact) ++m.contactPaints;
        if (meshViewport) {
            const auto& upload = meshViewport->lastUpload();
            (upload.full ? m.fullUploads : m.partialUploads) += 1;
            m.uploadedVertices += upload.vertices;
            m.uploadRanges += upload.ranges;
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
                    // Once the window is up (showing it sets the markers of its mode).
                    if (options.heatMap && mesh) viewport->setExerciseMarkers(wholeSurfaceHeat(*mesh));
                } else if (nowS > kMaxWaitForContactS) {
                    std::fprintf(stderr, "palpate: %s did not touch the mesh within %.0f s\n",
                                 qPrintable(options.deviceUri), kMaxWaitForContactS);
                    finish(true);
                }
                break;
            case Phase::Settling:
                if (nowS - contactAtS >= kSettleS) {
                    phase = Phase::Measuring;
                    m.measureStartS = nowS;
                    m.framesAtStart = viewport->framesDrawn();
                    m.cpuAtStartS = threadCpuS();
                }
                break;
            case Phase::Measuring:
                if (nowS - m.measureStartS >= options.seconds) {
                    m.measureEndS = nowS;
                    m.framesAtEnd = viewport->framesDrawn();
                    m.cpuAtEndS = threadCpuS();
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
    ViewportFacts facts;
    facts.glInfo = glWidget ? glRendererString(glWidget) : QString();
    facts.sizePx = viewport->widget()->size() * viewport->widget()->devicePixelRatioF();
    facts.kind = viewport->kind();
    facts.samples = meshViewport ? meshViewport->requestedSamples() : 0;
    facts.loopRateHz = window.hapticRateHz();
    facts.loadAtEnd = loadAverage();
    facts.vertexCount = vertexCount;
    facts.heatPoints = viewport->exerciseMarkers().heat.size();
    window.close();  // stops the haptic thread
    return printResult(m, facts, failed);
}

}  // namespace palpate
