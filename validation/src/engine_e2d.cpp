// SPDX-License-Identifier: MIT
#include "engine_e2d.hpp"

#include <e2d/physics/events.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/world.hpp>

#include <algorithm>
#include <sstream>
#include <vector>

namespace e2d::validation {
namespace {

namespace ph = e2d::physics;

ph::ShapeGeometry toGeometry(const scenes::ShapeDesc& s) {
    switch (s.kind) {
    case scenes::ShapeKind::Box:
        if (s.center == glm::vec2{0.0f} && s.angle == 0.0f) {
            return ph::makeBox(s.halfExtents.x, s.halfExtents.y);
        }
        return ph::makeOffsetBox(s.halfExtents.x, s.halfExtents.y, s.center, s.angle);
    case scenes::ShapeKind::Polygon:
        return ph::makePolygon(std::span<const ph::Vec2>(s.points.data(), s.points.size()), s.radius);
    case scenes::ShapeKind::Circle:
        return ph::Circle{s.center, s.radius};
    case scenes::ShapeKind::Capsule:
        return ph::Capsule{s.point1, s.point2, s.radius};
    case scenes::ShapeKind::Segment:
        return ph::Segment{s.point1, s.point2};
    }
    return ph::Circle{s.center, s.radius};
}

ph::BodyType toType(scenes::BodyKind kind) {
    switch (kind) {
    case scenes::BodyKind::Static:
        return ph::BodyType::Static;
    case scenes::BodyKind::Kinematic:
        return ph::BodyType::Kinematic;
    case scenes::BodyKind::Dynamic:
        return ph::BodyType::Dynamic;
    }
    return ph::BodyType::Static;
}

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
    def.solver.velocityIterations = c.velocityIterations;
    def.solver.positionIterations = c.positionIterations;
    def.solver.enableSleep = c.sleeping;
    def.solver.enableContinuous = c.continuous;
    return def;
}

class E2dEngine final : public Engine {
public:
    E2dEngine(const scenes::SceneDesc& scene, const EngineConfig& config)
        : timeStep_(scene.timeStep), world_(worldDef(scene, config)) {
        bodies_.reserve(scene.bodies.size());
        for (const scenes::BodyDesc& desc : scene.bodies) {
            ph::BodyDef def;
            def.type = toType(desc.kind);
            def.position = desc.position;
            def.angle = desc.angle;
            def.linearVelocity = desc.linearVelocity;
            def.angularVelocity = desc.angularVelocity;
            def.fixedRotation = desc.fixedRotation;
            def.isBullet = desc.bullet;
            const ph::BodyId body = world_.createBody(def);
            for (const scenes::ShapeDesc& shape : desc.shapes) {
                ph::ShapeDef sd;
                sd.density = shape.density;
                sd.friction = shape.friction;
                sd.restitution = shape.restitution;
                world_.createShape(body, sd, toGeometry(shape));
            }
            bodies_.push_back(body);
        }
    }

    void step() override { world_.step(timeStep_); }

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
    float timeStep_;
    ph::World world_;
    std::vector<ph::BodyId> bodies_;
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
        << d.contactPushMaxSpeed << " m/s; linear speed capped at " << d.maxLinearSpeed
        << " m/s; sleep after " << d.timeToSleep << " s below " << d.linearSleepTolerance
        << " m/s.";
    return out.str();
}

std::unique_ptr<Engine> makeE2dEngine(const scenes::SceneDesc& scene, const EngineConfig& config) {
    return std::make_unique<E2dEngine>(scene, config);
}

} // namespace e2d::validation
