// SPDX-License-Identifier: MIT
#include "engine_e2d.hpp"

#include <e2d/physics/events.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/world.hpp>
#include <e2d/scenes/e2d_builder.hpp>

#include <algorithm>
#include <sstream>
#include <vector>

namespace e2d::validation {
namespace {

namespace ph = e2d::physics;

ph::WorldDef worldDef(const scenes::SceneDesc& scene, const EngineConfig& c) {
    ph::WorldDef def;
    def.gravity = scene.gravity;
    def.collisionAlgorithm =
        c.collision == "gjk" ? ph::CollisionAlgorithm::GjkEpa : ph::CollisionAlgorithm::Sat;
    def.speculativeDistance = c.speculativeDistance;
    def.bodyCapacity = static_cast<int>(scene.bodies.size());
    def.solver.mode = c.solver == "classic" ? ph::SolverMode::Classic : ph::SolverMode::SoftStep;
    def.solver.subSteps = c.subSteps;
    def.solver.relaxIterations = c.relaxIterations;
    def.solver.jointSolver = c.jointSolver == "soft"           ? ph::JointSolver::Soft
                             : c.jointSolver == "gauss-seidel" ? ph::JointSolver::GaussSeidel
                                                               : ph::JointSolver::Direct;
    def.solver.velocityIterations = c.velocityIterations;
    def.solver.positionIterations = c.positionIterations;
    def.solver.enableSleep = c.sleeping;
    def.solver.enableContinuous = c.continuous;
    return def;
}

class E2dEngine final : public Engine {
public:
    E2dEngine(const scenes::SceneDesc& scene, const EngineConfig& config)
        : scene_(scenes::buildE2d(scene, worldDef(scene, config))), world_(scene_.world),
          bodies_(scene_.bodies), pushes_(scene), timeStep_(scene.timeStep) {}

    void step() override {
        if (!pushes_.empty()) {
            pushes_.apply(
                double(steps_) * timeStep_,
                [&](int i, glm::vec2 f) { world_.applyForceToCenter(bodies_[std::size_t(i)], f); },
                [&](int i, glm::vec2 j) {
                    world_.applyLinearImpulseToCenter(bodies_[std::size_t(i)], j);
                });
        }
        scene_.step();
        ++steps_;
    }

    [[nodiscard]] int bodyCount() const override { return static_cast<int>(bodies_.size()); }

    void readBodies(std::vector<BodyState>& out) const override {
        out.resize(bodies_.size());
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const ph::BodyId id = bodies_[i];
            BodyState& s = out[i];
            const ph::Transform xf = world_.transform(id);
            s.position = xf.p;
            s.angle = xf.q.angle();
            s.velocity = world_.linearVelocity(id);
            s.angularVelocity = world_.angularVelocity(id);
            s.dynamic = world_.bodyType(id) == ph::BodyType::Dynamic;
            if (s.dynamic) {
                const ph::MassData m = world_.massData(id);
                s.mass = m.mass;
                s.inertia = m.rotationalInertia;
            } else {
                s.mass = 0.0f;
                s.inertia = 0.0f;
            }
            s.awake = world_.isAwake(id);
        }
    }

    void readJointAnchors(std::vector<std::pair<glm::vec2, glm::vec2>>& out) const override {
        out.resize(scene_.joints.size());
        for (std::size_t i = 0; i < scene_.joints.size(); ++i) {
            out[i] = {world_.jointAnchorA(scene_.joints[i]), world_.jointAnchorB(scene_.joints[i])};
        }
    }

    [[nodiscard]] float maxPenetration() const override {
        float deepest = 0.0f;
        world_.forEachTouchingContact([&](const ph::ContactData& c) {
            for (int i = 0; i < c.manifold->pointCount; ++i) {
                deepest = std::max(deepest, -c.manifold->points[i].separation);
            }
        });
        return deepest;
    }

private:
    scenes::E2dScene scene_;
    ph::World& world_;
    const std::vector<ph::BodyId>& bodies_;
    Pushes pushes_;
    float timeStep_;
    long long steps_ = 0;
};

} // namespace

std::string e2dNotes() {
    // Read from the defaults, so the notes follow the library.
    const ph::SolverDef d;
    const ph::WorldDef w;
    auto rule = [](ph::MixingRule r) {
        switch (r) {
        case ph::MixingRule::GeometricMean:
            return "sqrt(a b)";
        case ph::MixingRule::Average:
            return "(a + b) / 2";
        case ph::MixingRule::Min:
            return "min(a, b)";
        case ph::MixingRule::Max:
            return "max(a, b)";
        case ph::MixingRule::Multiply:
            return "a b";
        }
        return "?";
    };
    std::ostringstream out;
    out << "e2d physics::World: shapes as the scene gives them (no skin); boxes are 4-vertex "
           "polygons, capsules and segments are native; speculative contacts within "
        << w.speculativeDistance << " m; restitution threshold " << d.restitutionThreshold
        << " m/s; friction mixed as " << rule(d.frictionMixing) << ", restitution as "
        << rule(d.restitutionMixing) << "; soft step: contact stiffness " << d.contactHertz
        << " Hz, damping ratio " << d.contactDampingRatio << ", push-out at most "
        << d.contactPushMaxSpeed << " m/s, joints' rigid rows " << d.jointHertz
        << " Hz, damping ratio " << d.jointDampingRatio << "; linear speed capped at "
        << d.maxLinearSpeed << " m/s; sleep after " << d.timeToSleep << " s below "
        << d.linearSleepTolerance << " m/s.";
    return out.str();
}

std::unique_ptr<Engine> makeE2dEngine(const scenes::SceneDesc& scene, const EngineConfig& config) {
    return std::make_unique<E2dEngine>(scene, config);
}

} // namespace e2d::validation
