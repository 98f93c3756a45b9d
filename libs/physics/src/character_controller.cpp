// SPDX-License-Identifier: MIT
#include <e2d/physics/character_controller.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/physics_system.hpp>

#include "object_pose.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>

namespace e2d::physics {

namespace {

// The mover's def in metres for a controller's def in world units.
CharacterMoverDef moverDef(const CharacterControllerDef& def, float unitsPerMetre, Vec2 position) {
    const float toMetres = 1.0f / unitsPerMetre;
    CharacterMoverDef m;
    m.capsule = {def.capsule.center1 * toMetres, def.capsule.center2 * toMetres,
                 def.capsule.radius * toMetres};
    m.position = position;
    m.up = def.up;
    m.skin = def.skin * toMetres;
    m.maxSlopeAngle = def.maxSlopeAngle;
    m.maxPushOut = def.maxPushOut * toMetres;
    m.groundSnapDistance = def.groundSnapDistance * toMetres;
    m.filter.categoryBits = def.category.bits();
    m.filter.maskBits = def.mask.bits();
    m.contactFilter = def.contactFilter;
    return m;
}

// The mover's checks are the controller's (at one unit per metre the numbers are the user's):
// only the function named differs.
void validate(const CharacterControllerDef& def) {
    try {
        CharacterMover probe(moverDef(def, 1.0f, {0.0f, 0.0f}));
    } catch (const core::Error& e) {
        constexpr std::string_view mover = "physics::CharacterMover::CharacterMover()";
        std::string message = e.what();
        if (message.starts_with(mover)) {
            message.replace(0, mover.size(), "physics::CharacterController::CharacterController()");
        }
        throw core::Error(message);
    }
}

// The capsule as a shape the World takes: one whose centres (nearly) coincide is a Circle.
ShapeGeometry worldGeometry(const Capsule& capsule) {
    if (distance(capsule.center1, capsule.center2) < kLinearSlop) {
        return Circle{0.5f * (capsule.center1 + capsule.center2), capsule.radius};
    }
    return capsule;
}

MoveResult inUnits(MoveResult r, float unitsPerMetre) {
    r.position *= unitsPerMetre;
    r.translation *= unitsPerMetre;
    r.groundPoint *= unitsPerMetre;
    r.groundVelocity *= unitsPerMetre;
    r.pushedOut *= unitsPerMetre;
    return r;
}

} // namespace

CharacterController::CharacterController(const CharacterControllerDef& def) : def_(def) {
    validate(def_);
}

CharacterController::~CharacterController() = default;

PhysicsSystem& CharacterController::sys() const {
    if (system_ == nullptr) {
        if (scene() == nullptr) {
            throw core::Error("physics::CharacterController::system(): the CharacterController has "
                              "no PhysicsSystem (its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

void CharacterController::onInitialize() {
    PhysicsSystem& system = sys();
    const float upm = system.unitsPerMetre();
    const detail::Pose pose = detail::worldPose(*gameObject(), upm);
    CharacterMoverDef md = moverDef(def_, upm, pose.position);
    // The object's own Colliders never block its character.
    md.contactFilter = [this, user = def_.contactFilter](const MoverContact& contact) {
        const Collider* own = sys().collider(contact.shape);
        if (own != nullptr && own->gameObject() == gameObject()) {
            return false;
        }
        return !user || user(contact);
    };
    mover_.emplace(std::move(md));
    writtenPosition_ = pose.position;
    system.registerCharacter(*this);
    if (def_.hasBody) {
        BodyDef bd;
        bd.type = BodyType::Kinematic;
        bd.position = pose.position;
        bd.fixedRotation = true;
        body_ = system.world().createBody(bd);
        ShapeDef sd;
        // move() reports the character's contacts and sensor overlaps itself (see the header).
        sd.enableContactEvents = false;
        sd.enableSensorEvents = false;
        sd.filter.categoryBits = def_.category.bits();
        sd.filter.maskBits = def_.mask.bits();
        shape_ = system.world().createShape(body_, sd, worldGeometry(mover_->def().capsule));
        mover_->setIgnoredBody(body_);
    }
    last_ = inUnits(mover_->lastMove(), upm);
}

void CharacterController::onTerminate() {
    if (mover_) {
        sys().unregisterCharacter(*this);
    }
    if (!body_.isNull() && sys().world().isValid(body_)) {
        sys().world().destroyBody(body_);
    }
    body_ = {};
    shape_ = {};
    mover_.reset();
    touching_.clear();
    sensors_.clear();
}

CharacterMover& CharacterController::mover() {
    if (!mover_) {
        throw core::Error(
            "physics::CharacterController::mover(): the object is not in a scene yet");
    }
    return *mover_;
}

const MoveResult& CharacterController::move(Vec2 motion) {
    if (!mover_) {
        throw core::Error("physics::CharacterController::move(): the object is not in a scene yet");
    }
    if (!isFinite(motion)) {
        core::throwError("physics::CharacterController::move()",
                         "motion must be finite, got " + core::formatVector(motion));
    }
    PhysicsSystem& system = sys();
    const float upm = system.unitsPerMetre();
    const detail::Pose pose = detail::worldPose(*gameObject(), upm);
    if (detail::movedApart(pose, writtenPosition_, pose.angle)) {
        mover_->setPosition(pose.position); // moved by hand since the last move
    }
    const MoveResult& r = mover_->move(system.world(), system.toMetres(motion));
    detail::setWorldPose(*gameObject(), {r.position, pose.angle}, upm);
    writtenPosition_ = detail::worldPose(*gameObject(), upm).position;
    if (!body_.isNull() && system.world().isValid(body_)) {
        system.world().setTransform(body_, r.position, 0.0f);
    }
    last_ = inUnits(r, upm);
    dispatchContactEvents();
    dispatchSensorEvents();
    return last_;
}

Vec2 CharacterController::clipVelocity(Vec2 velocity) const {
    return mover_ ? mover_->clipVelocity(velocity) : velocity;
}

namespace {

bool contains(const std::vector<ShapeId>& shapes, ShapeId shape) {
    return std::find(shapes.begin(), shapes.end(), shape) != shapes.end();
}

} // namespace

// One event to both sides: the character's object hears of the shape's Collider (if the shape
// has one), the Collider's object of the character. `contact` gives the point (enter events of
// solid shapes only).
template <class Event>
void CharacterController::tellBoth(ShapeId shape, const MoverContact* contact) {
    const float upm = sys().unitsPerMetre();
    Collider* other = sys().collider(shape);
    Event mine;
    mine.other = other != nullptr ? other->gameObject() : nullptr;
    mine.otherCollider = other;
    Event theirs;
    theirs.other = gameObject();
    theirs.otherCollider = this;
    if (contact != nullptr) {
        mine.pointCount = theirs.pointCount = 1;
        mine.points[0] = {contact->point * upm, -contact->normal, contact->separation * upm};
        theirs.points[0] = {contact->point * upm, contact->normal, contact->separation * upm};
    }
    gameObject()->dispatch(mine);
    if (other != nullptr) {
        other->gameObject()->dispatch(theirs);
    }
}

// Shapes that started or stopped touching the capsule since the last move.
void CharacterController::dispatchContactEvents() {
    scratch_.clear();
    for (const MoverContact& contact : mover_->contacts()) {
        if (!contains(scratch_, contact.shape)) {
            scratch_.push_back(contact.shape);
            if (!contains(touching_, contact.shape)) {
                tellBoth<CollisionEnter>(contact.shape, &contact);
            }
        }
    }
    for (ShapeId shape : touching_) {
        if (!contains(scratch_, shape)) {
            tellBoth<CollisionExit>(shape, nullptr);
        }
    }
    touching_.swap(scratch_);
}

// Sensors the capsule started or stopped overlapping since the last move.
void CharacterController::dispatchSensorEvents() {
    const World& world = sys().world();
    QueryFilter filter;
    filter.categoryBits = def_.category.bits();
    filter.maskBits = def_.mask.bits();
    filter.includeSensors = true;
    scratch_ = world.overlapShape(worldGeometry(mover_->worldCapsule()), Transform{}, filter);
    std::erase_if(scratch_, [&](ShapeId shape) { return !world.isSensor(shape); });
    for (ShapeId shape : scratch_) {
        if (!contains(sensors_, shape)) {
            tellBoth<TriggerEnter>(shape, nullptr);
        }
    }
    for (ShapeId shape : sensors_) {
        if (!contains(scratch_, shape)) {
            tellBoth<TriggerExit>(shape, nullptr);
        }
    }
    sensors_.swap(scratch_);
}

} // namespace e2d::physics
