#pragma once
// `palpate --benchmark-viewport [--seconds S] [--software-render]`: frame times of the viewport
// while the haptic loop (its real-time thread, sim:stroke) deforms a generated 100 000-vertex
// sphere. The viewport is shown maximised and redrawn as fast as it can: under OpenGL the next
// frame is requested as soon as the last one was swapped (frameSwapped), in software each repaint
// follows the last. Frame time is the time between consecutive finished frames, measured once the
// stroke presses (or after a short warm-up). Prints what was measured, one line of key=value
// results (frames, mean and p95 frame ms, fps, renderer) and the uploads per frame.

#include "widgets/ViewportFactory.h"

#include <QString>

#include <cstddef>

namespace palpate {

struct ViewportBenchmarkDef {
    double seconds = 5.0;
    std::size_t vertexCount = 100000;
    RendererChoice renderer = RendererChoice::Auto;
};

/// Runs the benchmark in the running QApplication. Returns the process exit code (0, or 1 on failure).
int runViewportBenchmark(const ViewportBenchmarkDef& options);

/// The command line's entry: `secondsText` from --seconds (a number > 0); 2 on a bad value.
int runViewportBenchmark(const QString& secondsText, bool softwareRender);

}  // namespace palpate
