#pragma once
// Measures a model's rendered transfer H(z), tool position to rendered force, where it has no
// simple closed form (the mass-spring kinds; docs/stability.md, "Rendered stiffness and
// passivity"): the real model is pressed at a vertex until its force settles, the tool then steps
// a little deeper along the vertex's rest normal, and the force's step response, divided by the
// step, gives the impulse response h[n] of the linearised model (the contact stays closed: the
// model is linear there). H(e^{j theta}) = sum h[n] e^{-j n theta}. Qt-free, not real-time.

#include "engine/core/TissueMesh.h"
#include "engine/models/DeformationModel.h"
#include "engine/stability/SampledPassivity.h"

#include <string>
#include <vector>

namespace palpate {

struct TransferProbeDef {
    double pressDepthMm = 0.5;      ///< the operating point: tool below the vertex's rest position
    double stepMm = 0.05;           ///< the step deeper (small against the press: the contact stays closed)
    double settleTolerance = 1e-6;  ///< settled: the force changes by less than this, relative, per tick...
    int settleTicks = 32;           ///< ...this many ticks in a row
    int maxTicks = 4000;            ///< per phase (press, step); beyond it the force "does not settle"
};

struct MeasuredTransfer {
    bool ok = false;
    std::string problem;                ///< why not, when !ok
    std::vector<double> impulseNPerMm;  ///< h[n], n = 0 the tick of the step
    double staticNPerMm = 0.0;          ///< sum of h: the static (DC) stiffness
    int pressTicks = 0;                 ///< ticks the press took to settle
    int stepTicks = 0;                  ///< ticks the step response took to settle

    /// H(e^{j theta}) from h (N/mm); captures the impulse response by value.
    RenderedTransfer transfer() const;
};

/// Steps `model` (from wherever it is; reset first for a clean start) with the tool at `vertex`, at
/// period `periodS`. Not ok when the contact opens, the touched vertex changes, a value is not
/// finite, or the force does not settle within the probe's ticks (an undamped model).
MeasuredTransfer measureRenderedTransfer(DeformationModel& model, const TissueMesh& mesh, VertexId vertex,
                                         double periodS, const TransferProbeDef& def = {});

/// The vertex with the most neighbours (the stiffest point of a mass-spring mesh; the lowest id of
/// a tie), where the probe presses.
VertexId highestValenceVertex(const TissueMesh& mesh);

}  // namespace palpate
