// SPDX-License-Identifier: MIT
// Joint scenes of the solver benchmark, built the same way in e2d and Box2D 2.4:
//   joint_grid_100x100: a net of 100 x 100 discs (radius 0.4 m, 1 m apart) joined to their
//     left and upper neighbours by revolute joints (19 794 joints), hanging from 7 static
//     discs in the middle of its top row; the discs do not collide (filtered out).
//   chain_400: 400 boxes (0.5 m x 0.125 m) hinged end to end, hanging from a static anchor
//     and released horizontally, so it swings down and folds onto itself (links collide with
//     all but their neighbours).
// Each benchmark iteration is one 60 Hz step, with sleep off, of a world built and settled
// once (as the contact scenes in solver.cpp).
#include "solver_joints.hpp"

#include <e2d/physics/world.hpp>

#include <box2d/box2d.h>

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace e2d::bench {

namespace {

namespace ph = e2d::physics;

constexpr float kTimeStep = 1.0f / 60.0f;
constexpr int kGrid = 100;
constexpr int kChainLinks = 400;

// One scene in e2d terms: bodies (position, static or not, shape) and joints (two body
// indices, anchors in each body's frame). Built into both engines from this.
struct Body {
    float x = 0.0f;
    float y = 0.0f;
    bool dynamic = true;
    bool disc = true; // else a box of half extents (hx, hy)
    float radius = 0.4f;
    float hx = 0.0f;
    float hy = 0.0f;
    bool collide = true;
};
struct Hinge {
    int a = 0;
    int b = 0;
    float ax = 0.0f;
    float ay = 0.0f;
    float bx = 0.0f;
    float by = 0.0f;
};
struct JointScene {
    std::vector<Body> bodies;
    std::vector<Hinge> hinges;
};

JointScene jointGrid(int n) {
    JointScene s;
    const float shift = 1.0f;
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            Body b;
            b.x = static_cast<float>(k) * shift;
            b.y = -static_cast<float>(i) * shift;
            b.dynamic = !(i == 0 && k >= n / 2 - 3 && k <= n / 2 + 3);
            b.collide = false;
            const int index = static_cast<int>(s.bodies.size());
            s.bodies.push_back(b);
            if (i > 0) {
                s.hinges.push_back({index - 1, index, 0.0f, -0.5f * shift, 0.0f, 0.5f * shift});
            }
            // Two static neighbours of the top row are not joined (e2d refuses a joint no force
            // can move; Box2D would skip it in the solver).
            if (k > 0 && (b.dynamic || s.bodies[static_cast<std::size_t>(index - n)].dynamic)) {
                s.hinges.push_back({index - n, index, 0.5f * shift, 0.0f, -0.5f * shift, 0.0f});
            }
        }
    }
    return s;
}

JointScene chain(int links) {
    JointScene s;
    Body anchor;
    anchor.x = 0.0f;
    anchor.y = 0.0f;
    anchor.dynamic = false;
    anchor.radius = 0.1f;
    anchor.collide = false;
    s.bodies.push_back(anchor);
    const float hx = 0.25f;
    for (int i = 0; i < links; ++i) {
        Body b;
        b.disc = false;
        b.hx = hx;
        b.hy = 0.0625f;
        b.x = (2.0f * static_cast<float>(i) + 1.0f) * hx;
        b.y = 0.0f;
        s.bodies.push_back(b);
        const int index = static_cast<int>(s.bodies.size()) - 1;
        s.hinges.push_back({index - 1, index, i == 0 ? 0.0f : hx, 0.0f, -hx, 0.0f});
    }
    return s;
}

struct E2dWorld {
    std::unique_ptr<ph::World> world;
    int joints = 0;
};

E2dWorld buildE2d(const JointScene& scene) {
    ph::WorldDef def;
    def.gravity = {0.0f, -10.0f};
    def.solver.mode = ph::SolverMode::SoftStep;
    def.solver.subSteps = 4;
    def.solver.enableSleep = false;
    def.bodyCapacity = static_cast<int>(scene.bodies.size());
    def.shapeCapacity = static_cast<int>(scene.bodies.size());
    def.jointCapacity = static_cast<int>(scene.hinges.size());
    E2dWorld out{std::make_unique<ph::World>(def), 0};
    std::vector<ph::BodyId> ids;
    ids.reserve(scene.bodies.size());
    for (const Body& b : scene.bodies) {
        ph::BodyDef bd;
        bd.type = b.dynamic ? ph::BodyType::Dynamic : ph::BodyType::Static;
        bd.position = {b.x, b.y};
        ph::BodyId id = out.world->createBody(bd);
        ph::ShapeDef sd;
        sd.density = 1.0f;
        if (!b.collide) {
            sd.filter.categoryBits = 2;
            sd.filter.maskBits = ~std::uint64_t{2};
        }
        if (b.disc) {
            out.world->createShape(id, sd, ph::Circle{{0.0f, 0.0f}, b.radius});
        } else {
            out.world->createShape(id, sd, ph::makeBox(b.hx, b.hy));
        }
        ids.push_back(id);
    }
    for (const Hinge& h : scene.hinges) {
        ph::RevoluteJointDef jd;
        jd.bodyA = ids[static_cast<std::size_t>(h.a)];
        jd.bodyB = ids[static_cast<std::size_t>(h.b)];
        jd.localAnchorA = {h.ax, h.ay};
        jd.localAnchorB = {h.bx, h.by};
        out.world->createJoint(jd);
        ++out.joints;
    }
    return out;
}

std::unique_ptr<b2World> buildBox2D(const JointScene& scene) {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    world->SetAllowSleeping(false);
    std::vector<b2Body*> bodies;
    bodies.reserve(scene.bodies.size());
    for (const Body& b : scene.bodies) {
        b2BodyDef bd;
        bd.type = b.dynamic ? b2_dynamicBody : b2_staticBody;
        bd.position.Set(b.x, b.y);
        b2Body* body = world->CreateBody(&bd);
        b2FixtureDef fd;
        fd.density = 1.0f;
        fd.friction = 0.6f;
        if (!b.collide) {
            fd.filter.categoryBits = 2;
            fd.filter.maskBits = static_cast<uint16>(~2u);
        }
        b2CircleShape circle;
        b2PolygonShape box;
        if (b.disc) {
            circle.m_radius = b.radius;
            fd.shape = &circle;
        } else {
            box.SetAsBox(b.hx, b.hy);
            fd.shape = &box;
        }
        body->CreateFixture(&fd);
        bodies.push_back(body);
    }
    for (const Hinge& h : scene.hinges) {
        b2RevoluteJointDef jd;
        jd.bodyA = bodies[static_cast<std::size_t>(h.a)];
        jd.bodyB = bodies[static_cast<std::size_t>(h.b)];
        jd.localAnchorA.Set(h.ax, h.ay);
        jd.localAnchorB.Set(h.bx, h.by);
        world->CreateJoint(&jd);
    }
    return world;
}

struct Case {
    std::string name;
    JointScene scene;
};

struct JointWorlds {
    int settleSteps = 120;
    std::vector<Case> cases;
    std::map<std::string, E2dWorld> e2d;
    std::map<std::string, std::unique_ptr<b2World>> box2d;
};

JointWorlds& jointWorlds() {
    static JointWorlds all;
    return all;
}

void stepE2d(benchmark::State& state, const Case* c) {
    JointWorlds& w = jointWorlds();
    E2dWorld& slot = w.e2d[c->name];
    if (!slot.world) {
        slot = buildE2d(c->scene);
        for (int i = 0; i < w.settleSteps; ++i) {
            slot.world->step(kTimeStep);
        }
    }
    double proxyMoves = 0.0;
    double jointRepacks = 0.0;
    double relaxSweeps = 0.0;
    for (auto _ : state) {
        slot.world->step(kTimeStep);
        proxyMoves += slot.world->stepCounters().proxyMoves;
        jointRepacks += slot.world->stepCounters().jointRepacks;
        relaxSweeps += slot.world->stepCounters().relaxIterations;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["proxy_moves"] = proxyMoves / static_cast<double>(state.iterations());
    state.counters["joint_repacks"] = jointRepacks / static_cast<double>(state.iterations());
    // Relax sweeps per sub-step (2 when no contact needed the push-out sweeps).
    state.counters["relax_sweeps"] = relaxSweeps / static_cast<double>(state.iterations());
    state.counters["bodies"] = static_cast<double>(c->scene.bodies.size());
    state.counters["joints"] = static_cast<double>(slot.world->jointCount());
    state.counters["contacts"] = static_cast<double>(slot.world->contactCount());
}

void stepBox2D(benchmark::State& state, const Case* c) {
    JointWorlds& w = jointWorlds();
    std::unique_ptr<b2World>& slot = w.box2d[c->name];
    if (!slot) {
        slot = buildBox2D(c->scene);
        for (int i = 0; i < w.settleSteps; ++i) {
            slot->Step(kTimeStep, 8, 3);
        }
    }
    for (auto _ : state) {
        slot->Step(kTimeStep, 8, 3);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["bodies"] = static_cast<double>(c->scene.bodies.size());
    state.counters["joints"] = static_cast<double>(slot->GetJointCount());
    state.counters["contacts"] = static_cast<double>(slot->GetContactCount());
}

} // namespace

void registerJointBenchmarks(int settleSteps) {
    JointWorlds& w = jointWorlds();
    w.settleSteps = settleSteps;
    w.cases.push_back({"joint_grid_100x100", jointGrid(kGrid)});
    w.cases.push_back({"chain_400", chain(kChainLinks)});
    for (const Case& c : w.cases) {
        benchmark::RegisterBenchmark(("step/" + c.name + "/box2d").c_str(), stepBox2D, &c)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("step/" + c.name + "/e2d").c_str(), stepE2d, &c)
            ->Unit(benchmark::kMillisecond);
    }
}

} // namespace e2d::bench
