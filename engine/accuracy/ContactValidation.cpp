#include "engine/accuracy/ContactValidation.h"

#include "engine/fem/ClosedForms.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace palpate {

std::string_view contactReferenceName(ContactReference r) { return r == ContactReference::Punch ? "punch" : "hertz"; }

std::optional<ContactReference> parseContactReference(std::string_view name) {
    if (name == "punch") return ContactReference::Punch;
    if (name == "hertz") return ContactReference::Hertz;
    return std::nullopt;
}

ContactCaseResult runContactCase(const ContactCase& c) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string e = joinedMessages(validateElasticMaterial(c.material)); !e.empty())
        throw std::invalid_argument(e);
    if (!std::isfinite(c.indentationOverRadius) || c.indentationOverRadius <= 0.0)
        throw std::invalid_argument("indentation over radius must be positive");
    GradedBlockDef blockOptions = c.block;
    blockOptions.contactRadiusMm = c.contactRadiusMm;
    blockOptions.contactRadiusOverSpacing = c.aOverH;
    const GradedBlock block = makeGradedBlock(blockOptions);

    ContactCaseResult r;
    r.reference = c.reference;
    r.aOverH = c.aOverH;
    r.poissonRatio = c.material.poissonRatio;
    const double a = c.contactRadiusMm;
    r.contactRadiusMm = a;
    if (c.reference == ContactReference::Punch) {
        r.indentationMm = c.indentationOverRadius * a;
    } else {
        r.sphereRadiusMm = a / c.indentationOverRadius;
        r.indentationMm = a * a / r.sphereRadiusMm;
    }
    const double delta = r.indentationMm;
    // A node exactly on r = a (on both axes, by construction) belongs to the contact.
    const double contactLimit = a * (1.0 + 1e-9);
    auto prescribedDepth = [&](double radius) {
        return c.reference == ContactReference::Punch ? delta : delta - radius * radius / (2.0 * r.sphereRadiusMm);
    };
    auto closedDepth = [&](double radius) {
        return c.reference == ContactReference::Punch ? punchSurfaceDisplacementMm(a, delta, radius)
                                                      : hertzSurfaceDisplacementMm(r.sphereRadiusMm, delta, radius);
    };
    r.forceClosedN = c.reference == ContactReference::Punch ? punchForceN(c.material, a, delta)
                                                            : hertzForceN(c.material, r.sphereRadiusMm, delta);

    // Fixed DOFs: symmetry (u_x = 0 on x = 0, u_y = 0 on y = 0), contact u_z, all of the far faces.
    const std::size_t nx = block.nx(), nz = block.nz();
    const TetMesh& mesh = block.mesh;
    std::vector<std::uint8_t> fixed(mesh.dofCount(), 0);
    std::vector<double> contactValues(mesh.dofCount(), 0.0);  // load case 0: contact, far faces at rest
    std::vector<double> farUnitValues(mesh.dofCount(), 0.0);  // load case 1: Boussinesq of P = 1 N
    std::vector<TetNodeId> contactNodes, errorNodes;
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < nx; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                const TetNodeId n = block.node(i, j, k);
                const glm::dvec3& p = mesh.nodesMm[n];
                if (i == 0) fixed[3 * n + 0] = 1;
                if (j == 0) fixed[3 * n + 1] = 1;
                if (i + 1 == nx || j + 1 == nx || k + 1 == nz) {
                    const glm::dvec3 u = boussinesqDisplacementMm(c.material, 1.0, p);
                    for (int d = 0; d < 3; ++d) {
                        fixed[3 * n + d] = 1;
                        farUnitValues[3 * n + d] = u[d];
                    }
                    continue;
                }
                if (k != 0) continue;
                const double radius = std::hypot(p.x, p.y);
                if (radius <= contactLimit) {
                    fixed[3 * n + 2] = 1;
                    contactValues[3 * n + 2] = -prescribedDepth(radius);
                    contactNodes.push_back(n);
                }
                if (radius <= 5.0 * a * (1.0 + 1e-9)) errorNodes.push_back(n);
            }
    LinearElasticFem fem(mesh, c.material, std::move(fixed), c.solver);
    const std::vector<FemSolution> solutions = fem.solveMany({contactValues, farUnitValues});
    const FemSolution& contact = solutions[0];
    const FemSolution& farUnit = solutions[1];

    // Force pushing in = -(sum of z reactions on the contact nodes), times 4 for the quarter model.
    auto contactForce = [&](const FemSolution& s) {
        double sum = 0.0;
        for (TetNodeId n : contactNodes) sum -= s.reactionN[n].z;
        return 4.0 * sum;
    };
    const double force0 = contactForce(contact);
    const double forcePerUnitLoad = contactForce(farUnit);  // dF/dP (negative: the far field pulls the contact along)

    // Self-consistent far-field load: P <- F(P) = F0 + P dF/dP, from P_0 = F0 (far faces at rest).
    // Each step equals a full solve with the far faces at Boussinesq(P) (linearity), so the
    // iteration costs no further solve. It contracts by |dF/dP| per step; when that is >= 1
    // (strong locking on coarse meshes) it cannot converge and the fixed point of the same linear
    // map, P = F0 / (1 - dF/dP), is taken instead (reported as loadSolvedDirectly).
    r.loadContraction = forcePerUnitLoad;
    double load = force0;
    bool converged = false;
    for (int it = 1; it <= c.maxLoadIterations; ++it) {
        const double next = force0 + load * forcePerUnitLoad;
        const double change = std::abs(next - load) / std::abs(next);
        if (it == 1) r.loadFirstChange = change;
        r.loadLastChange = change;
        r.loadIterations = it;
        load = next;
        if (change <= c.loadTolerance) {
            converged = true;
            break;
        }
    }
    if (!converged) {
        if (!(std::abs(1.0 - forcePerUnitLoad) > 1e-12)) throw std::runtime_error("far-field load has no fixed point");
        load = force0 / (1.0 - forcePerUnitLoad);
        r.loadSolvedDirectly = true;
    }
    r.forceFemN = load;
    r.forceError = std::abs(r.forceFemN - r.forceClosedN) / r.forceClosedN;

    double sumSq = 0.0;
    for (TetNodeId n : errorNodes) {
        const glm::dvec3& p = mesh.nodesMm[n];
        const double uz = contact.displacementMm[n].z + load * farUnit.displacementMm[n].z;
        const double e = (-uz - closedDepth(std::hypot(p.x, p.y))) / delta;
        sumSq += e * e;
    }
    r.displacementError = errorNodes.empty() ? std::numeric_limits<double>::quiet_NaN()
                                             : std::sqrt(sumSq / double(errorNodes.size()));
    r.contactNodes = contactNodes.size();
    r.errorNodes = errorNodes.size();
    r.nodes = mesh.nodeCount();
    r.tets = mesh.tetCount();
    r.freeDofs = fem.freeDofCount();
    r.solve = contact.stats;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        ++n;
    }
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    const double den = n * sxx - sx * sx;
    return den == 0.0 ? std::numeric_limits<double>::quiet_NaN() : (n * sxy - sx * sy) / den;
}

}  // namespace palpate
