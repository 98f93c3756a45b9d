// SPDX-License-Identifier: MIT
// Random worlds stepped for a few dozen steps: every shape type, sizes from 1e-3 to 1e3 m,
// densities from 1e-3 to 1e3 kg/m^2, static, kinematic and dynamic bodies, bullets, sensors,
// locks, random velocities, forces and impulses between steps, both solver modes and both
// collision algorithms. After every step each enabled body must have a finite state, and the
// bodies the step disabled must be exactly the ones it reported as non-finite. Non-finite
// input to the API must throw core::Error and change nothing. Anything else aborts.
#include <e2d/core/error.hpp>
#include <e2d/physics/world.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

using namespace e2d::physics;

// Aborts naming the failed check's line (libFuzzer's stack trace has no line numbers).
void check(bool condition, int line = __builtin_LINE()) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_world.cpp:%d: check failed\n", line);
        std::abort();
    }
}

float unit(FuzzedDataProvider& data) {
    return static_cast<float>(data.ConsumeIntegral<std::uint16_t>()) / 65535.0f;
}

float range(FuzzedDataProvider& data, float lo, float hi) { return lo + (hi - lo) * unit(data); }

// Log-uniform in [lo, hi]: sizes and densities spanning many decades.
float logRange(FuzzedDataProvider& data, float lo, float hi) {
    return lo * std::pow(hi / lo, unit(data));
}

Vec2 vec(FuzzedDataProvider& data, float extent) {
    return {range(data, -extent, extent), range(data, -extent, extent)};
}

// A value the API must reject: NaN or an infinity.
float nonFinite(FuzzedDataProvider& data) {
    switch (data.ConsumeIntegralInRange<int>(0, 2)) {
    case 0:
        return std::numeric_limits<float>::quiet_NaN();
    case 1:
        return std::numeric_limits<float>::infinity();
    default:
        return -std::numeric_limits<float>::infinity();
    }
}

// A vector with at least one non-finite component.
Vec2 badVec(FuzzedDataProvider& data) {
    Vec2 v = vec(data, 10.0f);
    int which = data.ConsumeIntegralInRange<int>(0, 2);
    if (which != 1) {
        v.x = nonFinite(data);
    }
    if (which != 0) {
        v.y = nonFinite(data);
    }
    return v;
}

ShapeGeometry makeGeometry(FuzzedDataProvider& data, float size, bool allowSegment) {
    int kind = data.ConsumeIntegralInRange<int>(0, allowSegment ? 4 : 3);
    Vec2 offset = 0.5f * size * vec(data, 1.0f);
    switch (kind) {
    case 0:
        return Circle{offset, size};
    case 1: {
        float angle = range(data, -3.2f, 3.2f);
        Vec2 axis{std::cos(angle), std::sin(angle)};
        // The axis must be at least kLinearSlop long.
        float half = std::max(size, kLinearSlop);
        return Capsule{offset - half * axis, offset + half * axis, 0.5f * size};
    }
    case 2:
        return makeOffsetBox(size, size * logRange(data, 0.1f, 1.0f), offset,
                             range(data, -3.2f, 3.2f));
    case 3: {
        int count = data.ConsumeIntegralInRange<int>(3, 8);
        std::vector<Vec2> points;
        for (int i = 0; i < count; ++i) {
            points.push_back(offset + size * vec(data, 1.0f));
        }
        float radius = data.ConsumeBool() ? 0.1f * size * unit(data) : 0.0f;
        try {
            return makePolygon(points, radius);
        } catch (const e2d::core::Error&) {
            return makeBox(size, size); // degenerate cloud: a box instead
        }
    }
    default: {
        float angle = range(data, -3.2f, 3.2f);
        Vec2 axis{std::cos(angle), std::sin(angle)};
        float half = std::max(2.0f * size, kLinearSlop);
        return Segment{offset - half * axis, offset + half * axis};
    }
    }
}

// What a rejected call must leave alone.
struct Snapshot {
    Transform transform;
    Vec2 linearVelocity;
    float angularVelocity;
    bool awake;
    bool enabled;
};

bool same(const Snapshot& a, const Snapshot& b) {
    return a.transform.p == b.transform.p && a.transform.q.c == b.transform.q.c &&
           a.transform.q.s == b.transform.q.s && a.linearVelocity == b.linearVelocity &&
           a.angularVelocity == b.angularVelocity && a.awake == b.awake && a.enabled == b.enabled;
}

Snapshot snapshot(const World& world, BodyId id) {
    return {world.transform(id), world.linearVelocity(id), world.angularVelocity(id),
            world.isAwake(id), world.isBodyEnabled(id)};
}

bool finiteState(const World& world, BodyId id) {
    Transform xf = world.transform(id);
    return isFinite(xf.p) && isFinite(xf.q.c) && isFinite(xf.q.s) &&
           isFinite(world.linearVelocity(id)) && isFinite(world.angularVelocity(id)) &&
           isFinite(world.worldCenterOfMass(id));
}

// Calls `bad` (which must throw core::Error) and checks that no body changed.
template <typename F>
void expectRejected(const World& world, const std::vector<BodyId>& bodies, F&& bad) {
    std::vector<Snapshot> before;
    for (BodyId id : bodies) {
        before.push_back(snapshot(world, id));
    }
    bool threw = false;
    try {
        bad();
    } catch (const e2d::core::Error&) {
        threw = true;
    }
    check(threw);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        check(same(before[i], snapshot(world, bodies[i])));
    }
}

void createBody(FuzzedDataProvider& data, World& world, std::vector<BodyId>& bodies, float extent) {
    BodyDef bd;
    int type = data.ConsumeIntegralInRange<int>(0, 9);
    bd.type = type < 2 ? BodyType::Static : type < 3 ? BodyType::Kinematic : BodyType::Dynamic;
    bd.position = vec(data, extent);
    bd.angle = range(data, -3.2f, 3.2f);
    if (bd.type != BodyType::Static) {
        float speed = data.ConsumeBool() ? 5.0f : 600.0f;
        bd.linearVelocity = vec(data, speed);
        bd.angularVelocity = range(data, -50.0f, 50.0f);
    }
    std::uint8_t flags = data.ConsumeIntegral<std::uint8_t>();
    bd.isBullet = (flags & 1) != 0;
    bd.fixedRotation = (flags & 2) != 0;
    bd.lockX = (flags & 0x1c) == 4;
    bd.lockY = (flags & 0x1c) == 8;
    bd.enableSleep = (flags & 0x20) == 0;
    bd.isAwake = (flags & 0x40) == 0;
    bd.enabled = (flags & 0x80) == 0 || data.ConsumeBool();
    bd.linearDamping = data.ConsumeBool() ? range(data, 0.0f, 5.0f) : 0.0f;
    bd.angularDamping = data.ConsumeBool() ? range(data, 0.0f, 5.0f) : 0.0f;
    bd.gravityScale = data.ConsumeBool() ? range(data, -2.0f, 3.0f) : 1.0f;
    BodyId id = world.createBody(bd);
    bodies.push_back(id);

    int shapeCount = data.ConsumeIntegralInRange<int>(1, 2);
    for (int i = 0; i < shapeCount; ++i) {
        ShapeDef sd;
        sd.density = logRange(data, 1.0e-3f, 1.0e3f);
        sd.friction = range(data, 0.0f, 1.0f);
        sd.restitution = data.ConsumeBool() ? range(data, 0.0f, 1.0f) : 0.0f;
        sd.rollingResistance = data.ConsumeBool() ? range(data, 0.0f, 0.2f) : 0.0f;
        sd.isSensor = data.ConsumeIntegralInRange<int>(0, 7) == 0;
        sd.filter.categoryBits = std::uint64_t{1} << data.ConsumeIntegralInRange<int>(0, 2);
        float size = logRange(data, 1.0e-3f, 1.0e3f);
        world.createShape(id, sd, makeGeometry(data, size, bd.type == BodyType::Static));
    }
}

// One call between steps: a valid change, or an invalid one that must be rejected.
// `absurd` collects the bodies given a finite but absurd value (3e38).
void act(FuzzedDataProvider& data, World& world, std::vector<BodyId>& bodies,
         std::vector<BodyId>& absurd) {
    if (bodies.empty()) {
        return;
    }
    BodyId id = bodies[data.ConsumeIntegralInRange<std::size_t>(0, bodies.size() - 1)];
    Vec2 point = world.worldCenterOfMass(id) + vec(data, 2.0f);
    bool wake = data.ConsumeBool();
    switch (data.ConsumeIntegralInRange<int>(0, 17)) {
    case 0:
        world.applyForce(id, vec(data, 1.0e4f), point, wake);
        break;
    case 1:
        world.applyForceToCenter(id, vec(data, 1.0e4f), wake);
        break;
    case 2:
        world.applyTorque(id, range(data, -1.0e4f, 1.0e4f), wake);
        break;
    case 3:
        world.applyLinearImpulse(id, vec(data, 1.0e3f), point, wake);
        break;
    case 4:
        world.applyLinearImpulseToCenter(id, vec(data, 1.0e3f), wake);
        break;
    case 5:
        world.applyAngularImpulse(id, range(data, -1.0e3f, 1.0e3f), wake);
        break;
    case 6:
        world.setLinearVelocity(id, vec(data, 600.0f));
        break;
    case 7:
        world.setAngularVelocity(id, range(data, -100.0f, 100.0f));
        break;
    case 8:
        world.setTransform(id, vec(data, 50.0f), range(data, -3.2f, 3.2f));
        break;
    case 9:
        world.setBodyEnabled(id, data.ConsumeBool());
        break;
    case 10:
        world.setAwake(id, data.ConsumeBool());
        break;
    case 11:
        world.setBullet(id, data.ConsumeBool());
        break;
    case 12:
        world.setPositionLocks(id, data.ConsumeBool(), data.ConsumeBool());
        break;
    case 13:
        // Absurd but finite: the world must either cope or disable and report the body.
        absurd.push_back(id);
        switch (data.ConsumeIntegralInRange<int>(0, 3)) {
        case 0:
            world.setAngularVelocity(id, 3.0e38f);
            break;
        case 1:
            world.applyForceToCenter(id, {3.0e38f, -3.0e38f});
            break;
        case 2:
            world.applyTorque(id, -3.0e38f);
            break;
        default:
            world.setGravityScale(id, 3.0e38f);
            break;
        }
        break;
    case 14: {
        Vec2 bad = badVec(data);
        switch (data.ConsumeIntegralInRange<int>(0, 5)) {
        case 0:
            expectRejected(world, bodies, [&] { world.applyForce(id, bad, point); });
            break;
        case 1:
            expectRejected(world, bodies, [&] { world.applyForce(id, {1.0f, 0.0f}, bad); });
            break;
        case 2:
            expectRejected(world, bodies, [&] { world.applyLinearImpulse(id, bad, point); });
            break;
        case 3:
            expectRejected(world, bodies, [&] { world.applyLinearImpulseToCenter(id, bad); });
            break;
        case 4:
            expectRejected(world, bodies, [&] { world.setLinearVelocity(id, bad); });
            break;
        default:
            expectRejected(world, bodies, [&] { world.setTransform(id, bad, 0.0f); });
            break;
        }
        break;
    }
    case 15: {
        float bad = nonFinite(data);
        switch (data.ConsumeIntegralInRange<int>(0, 5)) {
        case 0:
            expectRejected(world, bodies, [&] { world.applyTorque(id, bad); });
            break;
        case 1:
            expectRejected(world, bodies, [&] { world.applyAngularImpulse(id, bad); });
            break;
        case 2:
            expectRejected(world, bodies, [&] { world.setAngularVelocity(id, bad); });
            break;
        case 3:
            expectRejected(world, bodies, [&] { world.setTransform(id, {0.0f, 0.0f}, bad); });
            break;
        case 4:
            expectRejected(world, bodies, [&] { world.setGravityScale(id, bad); });
            break;
        default:
            expectRejected(world, bodies, [&] { world.step(bad); });
            break;
        }
        break;
    }
    case 16:
        world.destroyBody(id);
        bodies.erase(std::find(bodies.begin(), bodies.end(), id));
        break;
    default:
        expectRejected(world, bodies, [&] { world.setGravity(badVec(data)); });
        break;
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
    FuzzedDataProvider data(bytes, size);
    WorldDef def;
    def.gravity = data.ConsumeBool() ? Vec2{0.0f, -10.0f} : vec(data, 30.0f);
    def.collisionAlgorithm =
        data.ConsumeBool() ? CollisionAlgorithm::Sat : CollisionAlgorithm::GjkEpa;
    def.solver.mode = data.ConsumeBool() ? SolverMode::SoftStep : SolverMode::Classic;
    def.solver.subSteps = data.ConsumeIntegralInRange<int>(1, 8);
    def.solver.velocityIterations = data.ConsumeIntegralInRange<int>(1, 10);
    def.solver.positionIterations = data.ConsumeIntegralInRange<int>(0, 4);
    def.solver.enableSleep = data.ConsumeBool();
    def.solver.enableContinuous = data.ConsumeIntegralInRange<int>(0, 3) != 0;
    World world{def};

    std::vector<BodyId> bodies;
    std::vector<BodyId> absurd;
    float extent = logRange(data, 0.5f, 50.0f);
    int bodyCount = data.ConsumeIntegralInRange<int>(1, 12);
    for (int i = 0; i < bodyCount; ++i) {
        createBody(data, world, bodies, extent);
    }

    int steps = data.ConsumeIntegralInRange<int>(1, 30);
    for (int s = 0; s < steps && data.remaining_bytes() > 0; ++s) {
        int actions = data.ConsumeIntegralInRange<int>(0, 3);
        for (int a = 0; a < actions; ++a) {
            act(data, world, bodies, absurd);
        }
        std::vector<bool> enabledBefore;
        for (BodyId id : bodies) {
            enabledBefore.push_back(world.isBodyEnabled(id));
        }
        world.step(data.ConsumeBool() ? 1.0f / 60.0f : range(data, 0.0f, 0.1f));

        std::span<const BodyId> reported = world.nonFiniteBodies();
        std::span<const BodyId> outOfRange = world.outOfRangeBodies();
        // Sizes, masses and speeds in range never make a state non-finite. (An absurd body
        // may take a body it touches with it: an absurd angular velocity reaches the
        // restitution target before integration caps it, see the README.) Nor do they carry
        // a body past kHuge: positions stay within a few kilometres (speeds are capped where
        // positions move; seed tiny-body-out-of-range). A body that does leave the range is
        // disabled and reported out of range.
        check(!absurd.empty() || reported.empty());
        check(!absurd.empty() || outOfRange.empty());
        for (BodyId id : outOfRange) {
            check(world.isValid(id) && !world.isBodyEnabled(id));
        }
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            BodyId id = bodies[i];
            check(world.isValid(id));
            bool wasReported = std::find(reported.begin(), reported.end(), id) != reported.end();
            if (world.isBodyEnabled(id)) {
                check(finiteState(world, id));
                Rot q = world.transform(id).q;
                check(std::fabs(q.c * q.c + q.s * q.s - 1.0f) < 1.0e-3f);
                check(!wasReported);
            } else {
                // Only the step's own checks (non-finite, out of range) disable a body during
                // a step, and each reports what it disabled.
                bool wasOutOfRange =
                    std::find(outOfRange.begin(), outOfRange.end(), id) != outOfRange.end();
                check((wasReported || wasOutOfRange) == static_cast<bool>(enabledBefore[i]));
            }
        }
        for (BodyId id : reported) {
            check(world.isValid(id) && !world.isBodyEnabled(id));
        }
        for (const ContactHitEvent& e : world.hitEvents()) {
            check(isFinite(e.point) && isFinite(e.normal) && std::isfinite(e.approachSpeed));
        }
        for (const ContactBeginTouchEvent& e : world.contactBeginEvents()) {
            check(e.manifold.pointCount >= 1 && e.manifold.pointCount <= 2);
            check(isFinite(e.manifold.normal));
        }
        world.forEachTouchingContact([](const ContactData& c) {
            for (int i = 0; i < c.manifold->pointCount; ++i) {
                check(std::isfinite(c.manifold->points[i].separation));
                check(std::isfinite(c.manifold->points[i].normalImpulse));
                check(std::isfinite(c.manifold->points[i].tangentImpulse));
            }
        });
    }
    return 0;
}
