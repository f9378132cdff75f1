#pragma once
// The interface every deformation model implements, so models can be swapped and charted.

#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>

namespace palpate {

struct ModelDef;  // engine/models/ModelRegistry.h (which includes this header)

/// Ring index reported for a displaced vertex that is not in the active rings (it is relaxing).
inline constexpr std::uint8_t kRelaxingRing = 0xff;

/// What one haptic tick produced.
struct TickResult {
    VertexId touched = kNoVertex;  ///< vertex nearest to the tool tip (kNoVertex if none found)
    glm::vec3 forceN{0.0f};        ///< force rendered to the user (outward spring reaction)
    bool contact = false;          ///< the tissue pushes back on the tool (contact force > 0)
    float penetrationMm = 0.0f;    ///< depth of the tip below the displaced touched vertex, along its
                                   ///< rest normal, before this tick's update (< 0: above it)
    glm::vec3 normal{0.0f};        ///< unit outward direction of the normal contact force (zero
                                   ///< without contact); forceN minus its part along this is friction
    glm::vec3 proxyMm{0.0f};       ///< where the tool is held on the tissue: the proxy's centre for
                                   ///< a tool with a size (toolRadiusMm() > 0); zero for a point tool
};

class DeformationModel {
public:
    virtual ~DeformationModel() = default;
    /// One haptic tick: find the touched vertex, deform, return the force. Real-time safe.
    virtual TickResult step(const glm::vec3& toolTipMm, double dtS) = 0;
    /// Current vertex positions, in the mesh's vertex order.
    virtual std::span<const glm::vec3> positionsMm() const = 0;
    /// The current positions of the vertices `ids` into `out`, without writing any model state:
    /// what the haptic loop's guard reads each tick (a few vertices), so that a model whose
    /// positions are written when read (the coherent slope-ring method) keeps that saving.
    /// Real-time safe.
    virtual void copyPositionsMm(std::span<const VertexId> ids, glm::vec3* out) const {
        const std::span<const glm::vec3> all = positionsMm();
        for (std::size_t k = 0; k < ids.size(); ++k) out[k] = all[ids[k]];
    }
    /// True when every vertex copyDisplaced does not report is exactly at its rest position (the
    /// model moves only the vertices it lists): the loop's guard then need not sample the rest of
    /// the mesh for a blow-up. Models that integrate the whole mesh return false.
    virtual bool movesOnlyDisplaced() const { return false; }
    /// Back to the rest shape, no contact.
    virtual void reset() = 0;
    virtual std::string name() const = 0;
    /// The radius of the tool the model's contact assumes: 0 for a point tool (the position
    /// step() is given is the tip); > 0 for a sphere (the position is its centre).
    virtual float toolRadiusMm() const { return 0.0f; }

    /// The vertices away from rest, where they are, and which ring of the touched vertex each
    /// belongs to (kRelaxingRing when it is returning to rest), at most `capacity` of them; returns
    /// how many there are (more than `capacity` means the copy was cut). Real-time safe: the
    /// haptic loop publishes this to observers.
    virtual std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                      std::size_t capacity) const = 0;

    /// Reads (without changing anything) the memory the next step() will most likely touch, so
    /// that an idle core's cold caches and TLB are paid for before the deadline instead of inside
    /// the tick. The haptic loop calls it while it spins towards the deadline. Real-time safe.
    virtual void warm(const glm::vec3& /*lastToolTipMm*/) const {}

    /// Applies an already validated definition (validateModelDef) at a tick boundary: the model
    /// takes the parameters of its own kind when it can do so without reallocating. Returns false
    /// when it cannot (another kind or method, or parameters that need a new model: the caller
    /// builds one instead); the model is then unchanged. Real-time safe.
    virtual bool applyModelParams(const ModelDef& /*def*/) { return false; }
};

}  // namespace palpate
