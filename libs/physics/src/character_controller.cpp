// SPDX-License-Identifier: MIT
#include <e2d/physics/character_controller.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>

#include "error_format.hpp"
#include "object_pose.hpp"

#include <string>
#include <string_view>

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
    mover_.emplace(moverDef(def_, upm, pose.position));
    writtenPosition_ = pose.position;
    if (def_.hasBody) {
        BodyDef bd;
        bd.type = BodyType::Kinematic;
        bd.position = pose.position;
        bd.fixedRotation = true;
        body_ = system.world().createBody(bd);
        ShapeDef sd;
        sd.filter.categoryBits = def_.category.bits();
        sd.filter.maskBits = def_.mask.bits();
        shape_ = system.world().createShape(body_, sd, mover_->def().capsule);
        mover_->setIgnoredBody(body_);
    }
    last_ = inUnits(mover_->lastMove(), upm);
}

void CharacterController::onTerminate() {
    if (!body_.isNull() && sys().world().isValid(body_)) {
        sys().world().destroyBody(body_);
    }
    body_ = {};
    shape_ = {};
    mover_.reset();
}

CharacterMover& CharacterController::mover() {
    if (!mover_) {
        throw core::Error("physics::CharacterController::mover(): the object is not in a scene yet");
    }
    return *mover_;
}

const MoveResult& CharacterController::move(Vec2 motion) {
    if (!mover_) {
        throw core::Error("physics::CharacterController::move(): the object is not in a scene yet");
    }
    if (!isFinite(motion)) {
        detail::fail("physics::CharacterController::move()",
                     "motion must be finite, got " + detail::formatVec(motion));
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
    return last_;
}

Vec2 CharacterController::clipVelocity(Vec2 velocity) const {
    return mover_ ? mover_->clipVelocity(velocity) : velocity;
}

} // namespace e2d::physics
