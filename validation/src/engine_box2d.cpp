// SPDX-License-Identifier: MIT
#include "engine_box2d.hpp"

#include <e2d/scenes/box2d_builder.hpp>

#include <box2d/box2d.h>

#include <algorithm>

namespace e2d::validation {
namespace {

float skinOf(const b2Fixture* fixture) {
    const b2Shape::Type type = fixture->GetType();
    return type == b2Shape::e_polygon || type == b2Shape::e_edge || type == b2Shape::e_chain
               ? b2_polygonRadius
               : 0.0f;
}

class Box2DEngine final : public Engine {
public:
    Box2DEngine(const scenes::SceneDesc& scene, const EngineConfig& config)
        : timeStep_(scene.timeStep), pushes_(scene) {
        scenes::Box2DSettings settings;
        settings.velocityIterations = config.velocityIterations;
        settings.positionIterations = config.positionIterations;
        settings.allowSleeping = config.sleeping;
        settings.continuous = config.continuous;
        settings.warmStarting = config.warmStarting;
        scene_ = scenes::buildBox2D(scene, settings);
    }

    void step() override {
        if (!pushes_.empty()) {
            pushes_.apply(
                double(steps_) * timeStep_,
                [&](int i, glm::vec2 f) {
                    scene_.bodies[std::size_t(i)]->ApplyForceToCenter({f.x, f.y}, true);
                },
                [&](int i, glm::vec2 j) {
                    scene_.bodies[std::size_t(i)]->ApplyLinearImpulseToCenter({j.x, j.y}, true);
                });
        }
        scene_.step(timeStep_);
        ++steps_;
    }

    [[nodiscard]] int bodyCount() const override { return static_cast<int>(scene_.bodies.size()); }

    void readBodies(std::vector<BodyState>& out) const override {
        out.resize(scene_.bodies.size());
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
            const b2Body* body = scene_.bodies[i];
            BodyState& s = out[i];
            const b2Vec2 p = body->GetPosition();
            const b2Vec2 v = body->GetLinearVelocity();
            s.position = {p.x, p.y};
            s.angle = body->GetAngle();
            s.velocity = {v.x, v.y};
            s.angularVelocity = body->GetAngularVelocity();
            s.dynamic = body->GetType() == b2_dynamicBody;
            s.mass = body->GetMass();
            // GetInertia() is about the body origin; the metrics want it about the centre.
            const b2Vec2 c = body->GetLocalCenter();
            s.inertia = std::max(0.0f, body->GetInertia() - s.mass * b2Dot(c, c));
            s.awake = body->IsAwake();
        }
    }

    void readJointAnchors(std::vector<std::pair<glm::vec2, glm::vec2>>& out) const override {
        out.resize(scene_.joints.size());
        for (std::size_t i = 0; i < scene_.joints.size(); ++i) {
            const b2Vec2 a = scene_.joints[i]->GetAnchorA();
            const b2Vec2 b = scene_.joints[i]->GetAnchorB();
            out[i] = {{a.x, a.y}, {b.x, b.y}};
        }
    }

    [[nodiscard]] float maxPenetration() const override {
        // Box2D's separations are between the skinned shapes (polygons and edges grow by
        // b2_polygonRadius); the skin is not part of the scene, so it is added back to measure
        // the overlap of the shapes the scene describes, as for every other engine.
        float deepest = 0.0f;
        for (const b2Contact* c = scene_.world->GetContactList(); c != nullptr; c = c->GetNext()) {
            if (!c->IsTouching()) {
                continue;
            }
            b2WorldManifold wm;
            c->GetWorldManifold(&wm);
            const float skin = skinOf(c->GetFixtureA()) + skinOf(c->GetFixtureB());
            const int n = c->GetManifold()->pointCount;
            for (int i = 0; i < n; ++i) {
                deepest = std::max(deepest, -(wm.separations[i] + skin));
            }
        }
        return deepest;
    }

private:
    float timeStep_;
    Pushes pushes_;
    long long steps_ = 0;
    scenes::Box2DScene scene_;
};

} // namespace

std::string box2DNotes() {
    return "Box2D 2.4.1 (Debian libbox2d): every polygon carries a 0.01 m skin "
           "(b2_polygonRadius), so boxes placed exactly touching start 0.02 m overlapped and "
           "are pushed apart; linear slop 0.005 m; restitution threshold 1 m/s; at most 2 m of "
           "travel per step (b2_maxTranslation); segments are two-sided b2EdgeShapes; a capsule "
           "is two circles and a box on one body; a chain is a b2ChainShape (one-sided, like "
           "e2d's; an open end without a ghost point gets its end segment continued straight on, "
           "where e2d's end is free and round) or, with a material per segment, its one-sided "
           "child edges as separate fixtures; wheel and mouse springs take b2LinearStiffness of "
           "the scene's frequency for the two bodies' masses (e2d's soft springs use the "
           "constraint's effective mass); revolute and prismatic springs do not exist in 2.4.1, "
           "so such a scene fails on Box2D with that reason; penetration is measured between the "
           "shapes "
           "as the scene gives them (skin excluded), so a resting Box2D box shows a gap of up to "
           "0.015 m, not an overlap. Friction and restitution mix as sqrt(f1 f2) and max(e1, e2).";
}

std::unique_ptr<Engine> makeBox2DEngine(const scenes::SceneDesc& scene,
                                        const EngineConfig& config) {
    return std::make_unique<Box2DEngine>(scene, config);
}

} // namespace e2d::validation
