// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_check.hpp"
#include "world_impl.hpp"

#include <cstdint>
#include <string>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

namespace {

void validateWorldDef(const WorldDef& def) {
    const char* fn = "World";
    check::requireFinite(fn, "def.gravity", def.gravity);
    auto algorithm = static_cast<int>(def.collisionAlgorithm);
    if (algorithm != static_cast<int>(CollisionAlgorithm::Sat) &&
        algorithm != static_cast<int>(CollisionAlgorithm::GjkEpa)) {
        check::fail(fn, "def.collisionAlgorithm must be Sat or GjkEpa, got " +
                            std::to_string(algorithm));
    }
    // The speculative margin must stay inside the broad phase's fattening, or pairs within
    // the margin could be missed.
    if (!(isFinite(def.speculativeDistance) && def.speculativeDistance >= 0.0f &&
          def.speculativeDistance <= kAabbMargin)) {
        check::fail(fn, "def.speculativeDistance must be finite and in [0, kAabbMargin (" +
                            check::text(kAabbMargin) + " m)], got " +
                            check::text(def.speculativeDistance));
    }
    if (def.bodyCapacity < 0) {
        check::fail(fn, "def.bodyCapacity must be >= 0, got " + std::to_string(def.bodyCapacity));
    }
    if (def.jointCapacity < 0) {
        check::fail(fn, "def.jointCapacity must be >= 0, got " + std::to_string(def.jointCapacity));
    }
    if (def.shapeCapacity < 0) {
        check::fail(fn, "def.shapeCapacity must be >= 0, got " + std::to_string(def.shapeCapacity));
    }
    if (def.workerCount < 1 || def.workerCount > kMaxWorkers) {
        check::fail(fn, "def.workerCount must be in [1, " + std::to_string(kMaxWorkers) +
                            "], got " + std::to_string(def.workerCount));
    }
    if (def.minSplitWork < 0) {
        check::fail(fn, "def.minSplitWork must be >= 0, got " + std::to_string(def.minSplitWork));
    }
    if ((def.enqueueTask == nullptr) != (def.finishTask == nullptr)) {
        check::fail(fn,
                    std::string("def.enqueueTask and def.finishTask must both be set or both be "
                                "null, got only ") +
                        (def.enqueueTask != nullptr ? "enqueueTask" : "finishTask"));
    }
    if (def.simdLanes != 4 && def.simdLanes != 8) {
        check::fail(fn, "def.simdLanes must be 4 or 8, got " + std::to_string(def.simdLanes));
    }
}

void validateBodyDef(const BodyDef& def) {
    const char* fn = "createBody";
    auto type = static_cast<int>(def.type);
    if (type < 0 || type >= kBodyTypeCount) {
        check::fail(fn,
                    "def.type must be Static, Kinematic or Dynamic, got " + std::to_string(type));
    }
    check::requirePosition(fn, "def.position", def.position);
    check::requireFinite(fn, "def.angle", def.angle);
    check::requireFinite(fn, "def.linearVelocity", def.linearVelocity);
    check::requireFinite(fn, "def.angularVelocity", def.angularVelocity);
    check::requireNonNegative(fn, "def.linearDamping", def.linearDamping);
    check::requireNonNegative(fn, "def.angularDamping", def.angularDamping);
    check::requireFinite(fn, "def.gravityScale", def.gravityScale);
}

void validateShapeDef(const ShapeDef& def) {
    const char* fn = "createShape";
    check::requireNonNegative(fn, "def.density", def.density);
    check::requireNonNegative(fn, "def.friction", def.friction);
    if (!(isFinite(def.restitution) && def.restitution >= 0.0f && def.restitution <= 1.0f)) {
        check::fail(fn, "def.restitution must be finite and in [0, 1], got " +
                            check::text(def.restitution));
    }
    check::requireNonNegative(fn, "def.rollingResistance", def.rollingResistance);
}

// A world's tag when WorldDef::tag is 0: the address of its heap-allocated state (which moves
// with the World, so ids survive a move) mixed by the splitmix64 finaliser, folded to 16 bits,
// never 0. No counter: a process-wide counter would be global mutable state.
std::uint16_t tagFromAddress(const void* address) {
    auto x = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(address));
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    auto tag = static_cast<std::uint16_t>(x ^ (x >> 16) ^ (x >> 32) ^ (x >> 48));
    return tag == 0 ? std::uint16_t{1} : tag;
}

// "BodyId (index1 3, generation 1, world 4021)"
template <class Id>
std::string describe(const char* type, Id id) {
    return std::string(type) + " (index1 " + std::to_string(id.index1) + ", generation " +
           std::to_string(id.generation) + ", world " + std::to_string(id.owner) + ")";
}

template <class Id>
[[noreturn]] void failHandle(const char* function, const char* type, Id id, std::uint16_t tag) {
    if (!id.isNull() && id.owner != tag) {
        check::fail(function, describe(type, id) +
                                  " belongs to another world (this world's tag is " +
                                  std::to_string(tag) + ")");
    }
    check::fail(function, "stale or null " + describe(type, id));
}

} // namespace

// --- Impl ---

int World::Impl::require(BodyId id, const char* function) const {
    int index = find(id);
    if (index == kNullIndex) {
        failHandle(function, "BodyId", id, tag);
    }
    return index;
}

int World::Impl::require(ShapeId id, const char* function) const {
    int index = find(id);
    if (index == kNullIndex) {
        failHandle(function, "ShapeId", id, tag);
    }
    return index;
}

int World::Impl::require(JointId id, const char* function) const {
    int index = find(id);
    if (index == kNullIndex) {
        failHandle(function, "JointId", id, tag);
    }
    return index;
}

void World::Impl::requireUnlocked(const char* function) const {
    if (lockedBy != nullptr) {
        const std::string callback =
            lockedHook != nullptr ? std::string("the ") + lockedHook + " callback" : "the callback";
        check::fail(function, "cannot run inside " + callback + " of " + lockedBy +
                                  "() (it would change what the callback is walking); collect "
                                  "the ids and call it after " +
                                  lockedBy + "() returns");
    }
}

void World::Impl::createProxy(int shapeIndex) {
    detail::Shape& s = shape(shapeIndex);
    // A sensor that sees non-dynamic bodies lives in the dynamic tree whatever its body: moving
    // kinematic shapes look it up there, and its own moves look through every tree.
    const BodyType treeType =
        s.isSensor && s.sensorSeesNonDynamic ? BodyType::Dynamic : body(s.body).type;
    s.proxyKey = broadPhase.createProxy(s.aabb, treeType, s.filter.categoryBits,
                                        static_cast<std::uint64_t>(shapeIndex));
}

void World::Impl::destroyProxy(int shapeIndex) {
    detail::Shape& s = shape(shapeIndex);
    if (s.proxyKey != kNullIndex) {
        destroyContacts(shapeIndex);
        broadPhase.destroyProxy(s.proxyKey);
        s.proxyKey = kNullIndex;
    }
}

void World::Impl::destroyShapeAt(int shapeIndex) {
    destroyProxy(shapeIndex);
    detail::Shape& s = shape(shapeIndex);
    detail::Body& b = body(s.body);
    if (s.prevShape != kNullIndex) {
        shape(s.prevShape).nextShape = s.nextShape;
    } else {
        b.headShape = s.nextShape;
    }
    if (s.nextShape != kNullIndex) {
        shape(s.nextShape).prevShape = s.prevShape;
    }
    --b.shapeCount;
    s.alive = false;
    s.generation = core::nextGeneration(s.generation);
    int bodyIndex = s.body;
    s.body = s.prevShape = s.nextShape = kNullIndex;
    shapeIds.release(shapeIndex);
    updateMass(bodyIndex);
}

std::uint64_t World::Impl::pairQueryMask(int shapeIndex) const {
    // shouldCollide(): a shape pairs only with categories in its mask, unless both are in the
    // same positive group.
    const Filter& f = shape(shapeIndex).filter;
    return f.group > 0 ? DynamicTree::kAllBits : f.maskBits;
}

bool World::Impl::shouldPair(int shapeA, int shapeB) const {
    const detail::Shape& a = shape(shapeA);
    const detail::Shape& b = shape(shapeB);
    if (a.body == b.body) {
        return false;
    }
    if (a.isSensor && b.isSensor) {
        return false;
    }
    // Before the bodies are read: a filtered net or pile rejects most of its candidates here.
    if (!shouldCollide(a.filter, b.filter)) {
        return false;
    }
    // The broad phase already skips these (one tree per body type); this keeps the rule true
    // whatever it looks up.
    const BodyType typeA = body(a.body).type;
    const BodyType typeB = body(b.body).type;
    if (typeA != BodyType::Dynamic && typeB != BodyType::Dynamic) {
        // Only a sensor that sees non-dynamic bodies pairs without a dynamic body, and never
        // static with static.
        const bool wide =
            (a.isSensor && a.sensorSeesNonDynamic) || (b.isSensor && b.sensorSeesNonDynamic);
        if (!wide || (typeA == BodyType::Static && typeB == BodyType::Static)) {
            return false;
        }
    }
    if (body(a.body).jointHead != kNullIndex && body(b.body).jointHead != kNullIndex &&
        jointBlocksCollision(a.body, b.body)) {
        return false;
    }
    if (!hooks.pairFilter) {
        return true;
    }
    CallbackLock lock(*this, sim.inStep ? "step" : "updatePairs", "pair filter");
    return hooks.pairFilter(shapeId(shapeA), shapeId(shapeB));
}

// --- World ---

World::World(const WorldDef& def) {
    validateWorldDef(def);
    validate(def.solver);
    impl_ = std::make_unique<Impl>();
    impl_->sim.def = def.solver;
    impl_->gravity = def.gravity;
    impl_->collisionAlgorithm = def.collisionAlgorithm;
    impl_->speculativeDistance = def.speculativeDistance;
    impl_->tag = def.tag != 0 ? def.tag : tagFromAddress(impl_.get());
    impl_->tasks.configure(def.workerCount, def.minSplitWork, def.enqueueTask, def.finishTask,
                           def.userTaskContext);
    impl_->sim.simdLanes = def.simdLanes;
    impl_->bodies.reserve(static_cast<std::size_t>(def.bodyCapacity));
    impl_->bodyIds.reserve(def.bodyCapacity);
    impl_->shapes.reserve(static_cast<std::size_t>(def.shapeCapacity));
    impl_->shapeIds.reserve(def.shapeCapacity);
    impl_->joints.reserve(static_cast<std::size_t>(def.jointCapacity));
    impl_->jointIds.reserve(def.jointCapacity);
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Vec2 World::gravity() const { return impl_->gravity; }

void World::setGravity(Vec2 gravity) {
    check::requireFinite("setGravity", "gravity", gravity);
    impl_->gravity = gravity;
}

CollisionAlgorithm World::collisionAlgorithm() const { return impl_->collisionAlgorithm; }
float World::speculativeDistance() const { return impl_->speculativeDistance; }
std::uint16_t World::tag() const { return impl_->tag; }

BodyId World::createBody(const BodyDef& def) {
    impl_->requireUnlocked("createBody");
    validateBodyDef(def);
    Impl& w = *impl_;
    int index = w.bodyIds.allocate();
    if (index == static_cast<int>(w.bodies.size())) {
        w.bodies.emplace_back();
    }
    detail::Body& b = w.body(index);
    std::uint16_t generation = b.generation;
    b = detail::Body{};
    b.generation = generation;
    b.transform = {def.position, Rot::fromAngle(def.angle)};
    b.linearVelocity = def.linearVelocity;
    b.angularVelocity = def.angularVelocity;
    b.userData = def.userData;
    b.type = def.type;
    b.enabled = def.enabled;
    b.alive = true;
    w.initMotion(index, def);
    return w.bodyId(index);
}

void World::destroyBody(BodyId id) {
    impl_->requireUnlocked("destroyBody");
    Impl& w = *impl_;
    int index = w.require(id, "destroyBody");
    while (w.body(index).jointHead != kNullIndex) {
        w.destroyJointAt(w.body(index).jointHead);
    }
    while (w.body(index).headShape != kNullIndex) {
        w.destroyShapeAt(w.body(index).headShape);
    }
    detail::Body& b = w.body(index);
    b.alive = false;
    b.generation = core::nextGeneration(b.generation);
    w.bodyIds.release(index);
}

bool World::isValid(BodyId id) const { return impl_->find(id) != kNullIndex; }

BodyType World::bodyType(BodyId id) const {
    return impl_->body(impl_->require(id, "bodyType")).type;
}

Transform World::transform(BodyId id) const {
    return impl_->body(impl_->require(id, "transform")).transform;
}

void World::setTransform(BodyId id, Vec2 position, float angle) {
    impl_->requireUnlocked("setTransform");
    Impl& w = *impl_;
    int index = w.require(id, "setTransform");
    check::requirePosition("setTransform", "position", position);
    check::requireFinite("setTransform", "angle", angle);
    detail::Body& b = w.body(index);
    b.transform = {position, Rot::fromAngle(angle)};
    b.motion.positionResidual = {0.0f, 0.0f};
    w.wakeBody(index);
    for (int s = b.headShape; s != kNullIndex; s = w.shape(s).nextShape) {
        detail::Shape& shape = w.shape(s);
        shape.aabb = computeAabb(shape.geometry, b.transform);
        if (shape.proxyKey != kNullIndex) {
            w.broadPhase.moveProxy(shape.proxyKey, shape.aabb);
        }
    }
}

Vec2 World::linearVelocity(BodyId id) const {
    return impl_->body(impl_->require(id, "linearVelocity")).linearVelocity;
}

void World::setLinearVelocity(BodyId id, Vec2 velocity) {
    int index = impl_->require(id, "setLinearVelocity");
    check::requireFinite("setLinearVelocity", "velocity", velocity);
    impl_->body(index).linearVelocity = velocity;
    if (velocity.x != 0.0f || velocity.y != 0.0f) {
        impl_->wakeBody(index);
    }
}

float World::angularVelocity(BodyId id) const {
    return impl_->body(impl_->require(id, "angularVelocity")).angularVelocity;
}

void World::setAngularVelocity(BodyId id, float velocity) {
    int index = impl_->require(id, "setAngularVelocity");
    check::requireFinite("setAngularVelocity", "velocity", velocity);
    impl_->body(index).angularVelocity = velocity;
    if (velocity != 0.0f) {
        impl_->wakeBody(index);
    }
}

std::uint64_t World::bodyUserData(BodyId id) const {
    return impl_->body(impl_->require(id, "bodyUserData")).userData;
}

void World::setBodyUserData(BodyId id, std::uint64_t userData) {
    impl_->body(impl_->require(id, "setBodyUserData")).userData = userData;
}

bool World::isBodyEnabled(BodyId id) const {
    return impl_->body(impl_->require(id, "isBodyEnabled")).enabled;
}

void World::setBodyEnabled(BodyId id, bool enabled) {
    impl_->requireUnlocked("setBodyEnabled");
    Impl& w = *impl_;
    int index = w.require(id, "setBodyEnabled");
    if (w.body(index).enabled == enabled) {
        return;
    }
    w.body(index).enabled = enabled;
    if (enabled) {
        w.wakeBody(index);
    }
    for (int s = w.body(index).headShape; s != kNullIndex; s = w.shape(s).nextShape) {
        if (enabled) {
            w.createProxy(s);
        } else {
            w.destroyProxy(s);
        }
    }
}

std::vector<ShapeId> World::bodyShapes(BodyId id) const {
    const Impl& w = *impl_;
    int index = w.require(id, "bodyShapes");
    std::vector<ShapeId> result;
    result.reserve(static_cast<std::size_t>(w.body(index).shapeCount));
    for (int s = w.body(index).headShape; s != kNullIndex; s = w.shape(s).nextShape) {
        result.push_back(w.shapeId(s));
    }
    return result;
}

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const ShapeGeometry& geometry) {
    impl_->requireUnlocked("createShape");
    Impl& w = *impl_;
    int bodyIndex = w.require(bodyId, "createShape");
    validateShapeDef(def);
    validate(geometry, "physics::World::createShape()");

    int index = w.shapeIds.allocate();
    if (index == static_cast<int>(w.shapes.size())) {
        w.shapes.emplace_back();
    }
    detail::Shape& s = w.shape(index);
    std::uint16_t generation = s.generation;
    s = detail::Shape{};
    s.generation = generation;
    s.geometry = geometry;
    s.filter = def.filter;
    s.userData = def.userData;
    s.density = def.density;
    s.friction = def.friction;
    s.restitution = def.restitution;
    s.rollingResistance = def.rollingResistance;
    s.isSensor = def.isSensor;
    s.sensorSeesNonDynamic = def.sensorSeesNonDynamic;
    s.contactEvents = def.enableContactEvents;
    s.sensorEvents = def.enableSensorEvents;
    s.hitEvents = def.enableHitEvents;
    s.body = bodyIndex;

    detail::Body& b = w.body(bodyIndex);
    s.aabb = computeAabb(geometry, b.transform);
    s.nextShape = b.headShape;
    if (b.headShape != kNullIndex) {
        w.shape(b.headShape).prevShape = index;
    }
    b.headShape = index;
    ++b.shapeCount;
    s.alive = true;
    if (b.enabled) {
        w.createProxy(index);
    }
    w.updateMass(bodyIndex);
    return w.shapeId(index);
}

void World::destroyShape(ShapeId id) {
    impl_->requireUnlocked("destroyShape");
    impl_->destroyShapeAt(impl_->require(id, "destroyShape"));
}

bool World::isValid(ShapeId id) const { return impl_->find(id) != kNullIndex; }

BodyId World::shapeBody(ShapeId id) const {
    return impl_->bodyId(impl_->shape(impl_->require(id, "shapeBody")).body);
}

ShapeType World::shapeType(ShapeId id) const {
    return typeOf(impl_->shape(impl_->require(id, "shapeType")).geometry);
}

const ShapeGeometry& World::shapeGeometry(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeGeometry")).geometry;
}

Aabb World::shapeAabb(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeAabb")).aabb;
}

Aabb World::shapeFatAabb(ShapeId id) const {
    const detail::Shape& s = impl_->shape(impl_->require(id, "shapeFatAabb"));
    return s.proxyKey != kNullIndex ? impl_->broadPhase.fatAabb(s.proxyKey) : s.aabb;
}

Filter World::shapeFilter(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeFilter")).filter;
}

void World::setShapeFilter(ShapeId id, const Filter& filter) {
    impl_->requireUnlocked("setShapeFilter");
    Impl& w = *impl_;
    int index = w.require(id, "setShapeFilter");
    detail::Shape& s = w.shape(index);
    s.filter = filter;
    // Re-creating the proxy drops the shape's pairs and queues it as moved, so the next
    // updatePairs() pairs it again under the new filter; the tree also needs the new category.
    if (s.proxyKey != kNullIndex) {
        w.destroyProxy(index);
        w.createProxy(index);
    }
}

bool World::isSensor(ShapeId id) const {
    return impl_->shape(impl_->require(id, "isSensor")).isSensor;
}

float World::shapeDensity(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeDensity")).density;
}

float World::shapeFriction(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeFriction")).friction;
}

float World::shapeRestitution(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeRestitution")).restitution;
}

float World::shapeRollingResistance(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeRollingResistance")).rollingResistance;
}

std::uint64_t World::shapeUserData(ShapeId id) const {
    return impl_->shape(impl_->require(id, "shapeUserData")).userData;
}

void World::setShapeUserData(ShapeId id, std::uint64_t userData) {
    impl_->shape(impl_->require(id, "setShapeUserData")).userData = userData;
}

int World::bodyCount() const { return impl_->bodyIds.count(); }
int World::shapeCount() const { return impl_->shapeIds.count(); }

} // namespace e2d::physics
