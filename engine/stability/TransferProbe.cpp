#include "engine/stability/TransferProbe.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

/// One phase of the probe: the tool held at `depthMm`, ticks until the force settles. Appends
/// every tick's force (N, along the rest normal, outward) to `forces`; false with `problem` set
/// when the contact fails or the force does not settle.
std::string holdUntilSettled(DeformationModel& model, const TissueMesh& mesh, VertexId vertex, double periodS,
                             double depthMm, const TransferProbeDef& def, std::vector<double>& forces, int& ticks) {
    std::string problem;
    const glm::vec3 n = mesh.restNormals()[vertex];
    const glm::vec3 tool = mesh.restPositionsMm()[vertex] - float(depthMm) * n;
    int quiet = 0;
    double previous = 0.0;
    for (ticks = 0; ticks < def.maxTicks; ++ticks) {
        const TickResult r = model.step(tool, periodS);
        const double f = double(glm::dot(r.forceN, n));
        if (!std::isfinite(f)) {
            problem = "the rendered force is not finite";
            return problem;
        }
        if (!r.contact || r.touched != vertex) {
            problem = "the probe's contact opened or moved off the pressed vertex";
            return problem;
        }
        forces.push_back(f);
        quiet = ticks > 0 && std::abs(f - previous) <= def.settleTolerance * std::abs(f) ? quiet + 1 : 0;
        previous = f;
        if (quiet >= def.settleTicks) {
            ++ticks;
            return {};
        }
    }
    problem = "the rendered force does not settle within " + std::to_string(def.maxTicks) +
              " ticks (an undamped model rings for ever)";
    return problem;
}

}  // namespace

RenderedTransfer MeasuredTransfer::transfer() const {
    return [h = impulseNPerMm](double theta) {
        // sum h[n] e^{-j n theta} with the phasor advanced by multiplication (a few thousand terms:
        // the rounding stays ~1e-13).
        const std::complex<double> turn = std::polar(1.0, -theta);
        std::complex<double> phasor = 1.0, sum = 0.0;
        for (double hn : h) {
            sum += hn * phasor;
            phasor *= turn;
        }
        return sum;
    };
}

MeasuredTransfer measureRenderedTransfer(DeformationModel& model, const TissueMesh& mesh, VertexId vertex,
                                         double periodS, const TransferProbeDef& def) {
    MeasuredTransfer out;
    if (vertex >= mesh.vertexCount()) {
        out.problem = "no vertex to press";
        return out;
    }
    std::vector<double> press;
    if (!(out.problem = holdUntilSettled(model, mesh, vertex, periodS, def.pressDepthMm, def, press, out.pressTicks))
             .empty())
        return out;
    const double base = press.back();
    std::vector<double> step;
    if (!(out.problem = holdUntilSettled(model, mesh, vertex, periodS, def.pressDepthMm + def.stepMm, def, step,
                                         out.stepTicks))
             .empty())
        return out;
    // s[n] = (F_n - F_base) / step; h[0] = s[0], h[n] = s[n] - s[n - 1].
    out.impulseNPerMm.resize(step.size());
    double previous = 0.0;
    for (std::size_t i = 0; i < step.size(); ++i) {
        const double s = (step[i] - base) / def.stepMm;
        out.impulseNPerMm[i] = s - previous;
        previous = s;
    }
    out.staticNPerMm = previous;
    out.ok = true;
    return out;
}

VertexId highestValenceVertex(const TissueMesh& mesh) {
    const auto& start = mesh.neighbourStart();
    VertexId best = 0;
    for (VertexId v = 1; v + 1 < start.size(); ++v)
        if (start[v + 1] - start[v] > start[best + 1] - start[best]) best = v;
    return best;
}

}  // namespace palpate
