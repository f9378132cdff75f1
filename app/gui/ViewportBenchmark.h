#pragma once
// `palpate --benchmark-viewport [--mesh FILE] [--seconds S] [--software-render | --opengl-render] [--heat-map]`: the
// frame rate a user gets. The real main window (its docks, its ~60 Hz observer timer, the renderer the factory picks)
// shows the mesh while the haptic loop's real-time thread runs a device that keeps pressing (sim:sine: a press, then
// the depth swings, so every frame has a new dent to draw). Frames are counted once the tool is in contact, after a
// short settling time; the figures are the status bar's (frames painted over wall time) plus the spread of the frame
// intervals. Without --mesh a generated 100 000-vertex sphere. PALPATE_GL_SAMPLES=N forces the OpenGL viewport's
// multisampling (the baseline with the old 4x: docs/bench/README.md).

#include "widgets/ViewportFactory.h"

#include <QString>

#include <cstddef>

namespace palpate {

struct ViewportBenchmarkDef {
    double seconds = 5.0;
    QString meshPath;  ///< empty: a generated sphere of `vertexCount` vertices
    std::size_t vertexCount = 100000;
    RendererChoice renderer = RendererChoice::Auto;
    QString deviceUri = QStringLiteral("sim:sine");
    /// A coverage heat map over every vertex (the end of an examination of the whole surface).
    bool heatMap = false;
};

/// Runs the benchmark in the running QApplication. Returns the process exit code (0, or 1 on failure).
int runViewportBenchmark(const ViewportBenchmarkDef& options);

/// The command line's entry: `secondsText` from --seconds (a number > 0); 2 on a bad value.
int runViewportBenchmark(const QString& secondsText, const QString& meshPath, RendererChoice renderer,
                         bool heatMap = false);

}  // namespace palpate
