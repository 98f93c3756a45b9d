// SPDX-License-Identifier: MIT
// The body-level dynamics API of World: mass, damping, locks, forces, impulses, sleep flags,
// event arrays.
#include <e2d/physics/world.hpp>

#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

namespace {

// Smallest and largest distance from `center` to the shape's surface (metres).
struct Extents {
    float min = 0.0f;
    float max = 0.0f;
};

Extents extentsOf(const ShapeGeometry& geometry, Vec2 center) {
    return std::visit(
        [center](const auto& g) -> Extents {
            using T = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<T, Circle>) {
                return {g.radius, length(g.center - center) + g.radius};
            } else if constexpr (std::is_same_v<T, Capsule>) {
                return {g.radius, std::max(length(g.center1 - center), length(g.center2 - center)) +
                                      g.radius};
            } else if constexpr (std::is_same_v<T, Segment>) {
                return {kLinearSlop,
                        std::max(length(g.point1 - center), length(g.point2 - center))};
            } else if constexpr (std::is_same_v<T, ChainSegment>) {
                return {kLinearSlop, std::max(length(g.segment.point1 - center),
                                              length(g.segment.point2 - center))};
            } else {
                float minExtent = kHuge;
                float maxExtent = 0.0f;
                for (int i = 0; i < g.count; ++i) {
                    Vec2 v = g.vertices[static_cast<std::size_t>(i)];
                    float planeOffset = dot(g.normals[static_cast<std::size_t>(i)], v - g.centroid);
                    minExtent = std::min(minExtent, planeOffset);
                    maxExtent = std::max(maxExtent, length(v - center));
                }
                return {minExtent + g.radius, maxExtent + g.radius};
            }
        },
        geometry);
}

} // namespace

// --- Impl ---

void World::Impl::initMotion(int bodyIndex, const BodyDef& def) {
    detail::BodyMotion& m = body(bodyIndex).motion;
    m = detail::BodyMotion{};
    m.linearDamping = def.linearDamping;
    m.angularDamping = def.angularDamping;
    m.gravityScale = def.gravityScale;
    m.fixedRotation = def.fixedRotation;
    m.lockX = def.lockX;
    m.lockY = def.lockY;
    m.isBullet = def.isBullet;
    m.enableSleep = def.enableSleep;
    m.awake = def.isAwake && def.type != BodyType::Static;
    updateMass(bodyIndex);
}

void World::Impl::updateMass(int bodyIndex) {
    detail::Body& b = body(bodyIndex);
    detail::BodyMotion& m = b.motion;
    m.mass = 0.0f;
    m.inertia = 0.0f;
    m.invMass = 0.0f;
    m.invInertia = 0.0f;
    m.localCenter = {0.0f, 0.0f};
    float rotationalInertia = 0.0f;
    if (b.type == BodyType::Dynamic) {
        Vec2 weighted{0.0f, 0.0f};
        for (int s = b.headShape; s != kNullIndex; s = shape(s).nextShape) {
            const detail::Shape& sh = shape(s);
            if (sh.density == 0.0f) {
                continue;
            }
            MassData md = computeMass(sh.geometry, sh.density);
            m.mass += md.mass;
            weighted += md.mass * md.center;
            rotationalInertia += md.rotationalInertia + md.mass * dot(md.center, md.center);
        }
        if (m.mass > 0.0f) {
            m.localCenter = weighted / m.mass;
            // Parallel axis theorem: from the origin to the centre of mass.
            rotationalInertia -= m.mass * dot(m.localCenter, m.localCenter);
        } else {
            // A dynamic body without density still falls: a unit mass at its origin.
            m.mass = 1.0f;
            rotationalInertia = 0.0f;
        }
        m.invMass = 1.0f / m.mass;
        if (rotationalInertia > 0.0f && !m.fixedRotation) {
            m.inertia = rotationalInertia;
            m.invInertia = 1.0f / rotationalInertia;
        }
    }
    m.minExtent = kHuge;
    m.maxExtent = 0.0f;
    for (int s = b.headShape; s != kNullIndex; s = shape(s).nextShape) {
        Extents e = extentsOf(shape(s).geometry, m.localCenter);
        m.minExtent = std::min(m.minExtent, e.min);
        m.maxExtent = std::max(m.maxExtent, e.max);
    }
    if (b.headShape == kNullIndex) {
        m.minExtent = 0.0f;
    }
}

// --- World ---

const SolverDef& World::solverDef() const { return impl_->sim.def; }

MassData World::massData(BodyId id) const {
    const detail::BodyMotion& m = impl_->body(impl_->require(id, "massData")).motion;
    return {m.mass, m.localCenter, m.inertia};
}

void World::setMassData(BodyId id, const MassData& massData) {
    Impl& w = *impl_;
    const char* fn = "setMassData";
    int index = w.require(id, fn);
    if (w.body(index).type != BodyType::Dynamic) {
        check::fail(fn, "the body must be dynamic");
    }
    if (!(isFinite(massData.mass) && massData.mass > 0.0f)) {
        check::fail(fn, "massData.mass must be finite and > 0, got " + check::text(massData.mass));
    }
    check::requireFinite(fn, "massData.center", massData.center);
    check::requireNonNegative(fn, "massData.rotationalInertia", massData.rotationalInertia);
    detail::BodyMotion& m = w.body(index).motion;
    m.mass = massData.mass;
    m.invMass = 1.0f / massData.mass;
    m.localCenter = massData.center;
    m.inertia = m.fixedRotation ? 0.0f : massData.rotationalInertia;
    m.invInertia = m.inertia > 0.0f ? 1.0f / m.inertia : 0.0f;
}

Vec2 World::worldCenterOfMass(BodyId id) const {
    const detail::Body& b = impl_->body(impl_->require(id, "worldCenterOfMass"));
    return transformPoint(b.transform, b.motion.localCenter);
}

float World::linearDamping(BodyId id) const {
    return impl_->body(impl_->require(id, "linearDamping")).motion.linearDamping;
}

void World::setLinearDamping(BodyId id, float damping) {
    int index = impl_->require(id, "setLinearDamping");
    check::requireNonNegative("setLinearDamping", "damping", damping);
    impl_->body(index).motion.linearDamping = damping;
}

float World::angularDamping(BodyId id) const {
    return impl_->body(impl_->require(id, "angularDamping")).motion.angularDamping;
}

void World::setAngularDamping(BodyId id, float damping) {
    int index = impl_->require(id, "setAngularDamping");
    check::requireNonNegative("setAngularDamping", "damping", damping);
    impl_->body(index).motion.angularDamping = damping;
}

float World::gravityScale(BodyId id) const {
    return impl_->body(impl_->require(id, "gravityScale")).motion.gravityScale;
}

void World::setGravityScale(BodyId id, float scale) {
    int index = impl_->require(id, "setGravityScale");
    check::requireFinite("setGravityScale", "scale", scale);
    impl_->body(index).motion.gravityScale = scale;
}

bool World::isFixedRotation(BodyId id) const {
    return impl_->body(impl_->require(id, "isFixedRotation")).motion.fixedRotation;
}

void World::setFixedRotation(BodyId id, bool fixed) {
    Impl& w = *impl_;
    int index = w.require(id, "setFixedRotation");
    w.body(index).motion.fixedRotation = fixed;
    w.body(index).angularVelocity = fixed ? 0.0f : w.body(index).angularVelocity;
    w.updateMass(index);
}

void World::setPositionLocks(BodyId id, bool lockX, bool lockY) {
    Impl& w = *impl_;
    detail::Body& b = w.body(w.require(id, "setPositionLocks"));
    b.motion.lockX = lockX;
    b.motion.lockY = lockY;
    if (lockX) {
        b.linearVelocity.x = 0.0f;
    }
    if (lockY) {
        b.linearVelocity.y = 0.0f;
    }
}

bool World::isLockedX(BodyId id) const {
    return impl_->body(impl_->require(id, "isLockedX")).motion.lockX;
}

bool World::isLockedY(BodyId id) const {
    return impl_->body(impl_->require(id, "isLockedY")).motion.lockY;
}

bool World::isBullet(BodyId id) const {
    return impl_->body(impl_->require(id, "isBullet")).motion.isBullet;
}

void World::setBullet(BodyId id, bool bullet) {
    impl_->body(impl_->require(id, "setBullet")).motion.isBullet = bullet;
}

void World::applyForce(BodyId id, Vec2 force, Vec2 point, bool wake) {
    Impl& w = *impl_;
    const char* fn = "applyForce";
    int index = w.require(id, fn);
    check::requireFinite(fn, "force", force);
    check::requireFinite(fn, "point", point);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        Vec2 center = transformPoint(b.transform, b.motion.localCenter);
        b.motion.force += force;
        b.motion.torque += cross(point - center, force);
    }
}

void World::applyForceToCenter(BodyId id, Vec2 force, bool wake) {
    Impl& w = *impl_;
    int index = w.require(id, "applyForceToCenter");
    check::requireFinite("applyForceToCenter", "force", force);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        b.motion.force += force;
    }
}

void World::applyTorque(BodyId id, float torque, bool wake) {
    Impl& w = *impl_;
    int index = w.require(id, "applyTorque");
    check::requireFinite("applyTorque", "torque", torque);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        b.motion.torque += torque;
    }
}

namespace {

Vec2 lockedInvMass(const detail::BodyMotion& m) {
    return {m.lockX ? 0.0f : m.invMass, m.lockY ? 0.0f : m.invMass};
}

} // namespace

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point, bool wake) {
    Impl& w = *impl_;
    const char* fn = "applyLinearImpulse";
    int index = w.require(id, fn);
    check::requireFinite(fn, "impulse", impulse);
    check::requireFinite(fn, "point", point);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        Vec2 invMass = lockedInvMass(b.motion);
        Vec2 center = transformPoint(b.transform, b.motion.localCenter);
        b.linearVelocity += Vec2{invMass.x * impulse.x, invMass.y * impulse.y};
        b.angularVelocity += b.motion.invInertia * cross(point - center, impulse);
    }
}

void World::applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake) {
    Impl& w = *impl_;
    int index = w.require(id, "applyLinearImpulseToCenter");
    check::requireFinite("applyLinearImpulseToCenter", "impulse", impulse);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        Vec2 invMass = lockedInvMass(b.motion);
        b.linearVelocity += Vec2{invMass.x * impulse.x, invMass.y * impulse.y};
    }
}

void World::applyAngularImpulse(BodyId id, float impulse, bool wake) {
    Impl& w = *impl_;
    int index = w.require(id, "applyAngularImpulse");
    check::requireFinite("applyAngularImpulse", "impulse", impulse);
    detail::Body& b = w.body(index);
    if (b.type != BodyType::Dynamic) {
        return;
    }
    if (wake) {
        w.wakeBody(index);
    }
    if (b.motion.awake) {
        b.angularVelocity += b.motion.invInertia * impulse;
    }
}

bool World::isAwake(BodyId id) const {
    return impl_->body(impl_->require(id, "isAwake")).motion.awake;
}

bool World::isSleepEnabled(BodyId id) const {
    return impl_->body(impl_->require(id, "isSleepEnabled")).motion.enableSleep;
}

void World::setSleepEnabled(BodyId id, bool enabled) {
    Impl& w = *impl_;
    int index = w.require(id, "setSleepEnabled");
    w.body(index).motion.enableSleep = enabled;
    if (!enabled) {
        w.wakeBody(index);
    }
}

int World::awakeBodyCount() const {
    int count = 0;
    for (std::size_t i = 0; i < impl_->bodies.size(); ++i) {
        const detail::Body& b = impl_->bodies[i];
        count += b.alive && b.enabled && b.type != BodyType::Static && b.motion.awake ? 1 : 0;
    }
    return count;
}

std::span<const ContactBeginTouchEvent> World::contactBeginEvents() const {
    return impl_->sim.beginEvents;
}
std::span<const ContactEndTouchEvent> World::contactEndEvents() const {
    return impl_->sim.endEvents;
}
std::span<const SensorBeginTouchEvent> World::sensorBeginEvents() const {
    return impl_->sim.sensorBeginEvents;
}
std::span<const SensorEndTouchEvent> World::sensorEndEvents() const {
    return impl_->sim.sensorEndEvents;
}
std::span<const ContactHitEvent> World::hitEvents() const { return impl_->sim.hitEvents; }
std::span<const BodyId> World::nonFiniteBodies() const { return impl_->sim.nonFiniteBodies; }
std::span<const BodyId> World::outOfRangeBodies() const { return impl_->sim.outOfRangeBodies; }

StepCounters World::stepCounters() const { return impl_->sim.counters; }

int World::contactCount() const { return impl_->sim.contactCount; }

void World::forEachTouchingContact(FunctionRef<void(const ContactData&)> callback) const {
    Impl::CallbackLock lock(*impl_, "forEachTouchingContact");
    const detail::Simulation& s = impl_->sim;
    for (std::size_t i = 0; i < s.contacts.size(); ++i) {
        const detail::Contact& c = s.contacts[i];
        if (c.alive && c.touching && !c.sensor) {
            callback(ContactData{s.contactLinks[i].idA, s.contactLinks[i].idB, &c.manifold});
        }
    }
}

void World::setTargetTransform(BodyId id, Vec2 position, float angle, float timeStep) {
    Impl& w = *impl_;
    const int index = w.require(id, "setTargetTransform");
    check::requirePosition("setTargetTransform", "position", position);
    check::requireFinite("setTargetTransform", "angle", angle);
    if (!(isFinite(timeStep) && timeStep > 0.0f)) {
        check::fail("setTargetTransform",
                    "timeStep must be finite and > 0, got " + check::text(timeStep));
    }
    const detail::Body& b = w.body(index);
    if (b.type == BodyType::Static) {
        check::fail("setTargetTransform", "the body is static (it never moves)");
    }
    // The linear velocity is the centre of mass's: aim the centre at where it is at the target.
    const Transform target{position, Rot::fromAngle(angle)};
    const Vec2 from = transformPoint(b.transform, b.motion.localCenter);
    const Vec2 to = transformPoint(target, b.motion.localCenter);
    float turn = angle - b.transform.q.angle();
    constexpr float kPi = 3.14159265358979f;
    turn = std::remainder(turn, 2.0f * kPi);
    setLinearVelocity(id, (to - from) / timeStep);
    setAngularVelocity(id, b.motion.fixedRotation ? 0.0f : turn / timeStep);
}

} // namespace e2d::physics
