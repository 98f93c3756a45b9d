// SPDX-License-Identifier: MIT
#include <e2d/physics/character_mover.hpp>

#include <e2d/core/error_text.hpp>
#include <e2d/physics/world.hpp>

#include "mover_query.hpp"
#include "mover_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics {

namespace {

constexpr const char* kConstructor = "physics::CharacterMover::CharacterMover()";
constexpr float kHalfPi = 1.57079633f;
// Below this a pass moved nothing worth another pass, metres.
constexpr float kStill = 1.0e-6f;
// A slope too steep to stand on pushes back horizontally (it cannot lift the mover), unless it is
// so nearly flat that a horizontal push would have to be huge (maxSlopeAngle near 0).
constexpr float kMinHorizontal = 0.05f;

void requireField(bool ok, const char* field, const std::string& rule, const std::string& got) {
    if (!ok) {
        core::throwError(kConstructor,
                         std::string("def.") + field + " must be " + rule + ", got " + got);
    }
}

CharacterMoverDef checked(CharacterMoverDef def) {
    const Capsule& c = def.capsule;
    requireField(isWithinHuge(c.center1), "capsule.center1", "finite and within kHuge",
                 core::formatVector(c.center1));
    requireField(isWithinHuge(c.center2), "capsule.center2", "finite and within kHuge",
                 core::formatVector(c.center2));
    requireField(isWithinHuge(c.radius) && c.radius > 0.0f, "capsule.radius", "finite and > 0",
                 core::formatNumber(c.radius));
    requireField(isWithinHuge(def.position), "position", "finite and within kHuge",
                 core::formatVector(def.position));
    requireField(isFinite(def.up) && std::fabs(length(def.up) - 1.0f) <= 1.0e-3f, "up",
                 "a unit vector", core::formatVector(def.up));
    requireField(std::isfinite(def.skin) && def.skin >= 0.0f && def.skin <= c.radius, "skin",
                 "finite and in [0, capsule.radius = " + core::formatNumber(c.radius) + "]",
                 core::formatNumber(def.skin));
    requireField(std::isfinite(def.maxSlopeAngle) && def.maxSlopeAngle >= 0.0f &&
                     def.maxSlopeAngle < kHalfPi,
                 "maxSlopeAngle", "finite and in [0, pi/2) radians",
                 core::formatNumber(def.maxSlopeAngle));
    requireField(std::isfinite(def.maxPushOut) && def.maxPushOut > 0.0f, "maxPushOut",
                 "finite and > 0", core::formatNumber(def.maxPushOut));
    requireField(std::isfinite(def.groundSnapDistance) && def.groundSnapDistance >= 0.0f,
                 "groundSnapDistance", "finite and >= 0",
                 core::formatNumber(def.groundSnapDistance));
    def.up = normalize(def.up);
    return def;
}

} // namespace

CharacterMover::CharacterMover(const CharacterMoverDef& def)
    : def_(checked(def)), position_(def.position), cosMaxSlope_(std::cos(def.maxSlopeAngle)) {
    last_.position = position_;
}

void CharacterMover::setPosition(Vec2 position) {
    if (!isWithinHuge(position)) {
        core::throwError("physics::CharacterMover::setPosition()",
                         "position must be finite and within kHuge, got " +
                             core::formatVector(position));
    }
    position_ = position;
    last_ = MoveResult{};
    last_.position = position;
    contacts_.clear();
}

void CharacterMover::setContactFilter(MoverContactFilter filter) {
    def_.contactFilter = std::move(filter);
}

Capsule CharacterMover::worldCapsule() const {
    return {def_.capsule.center1 + position_, def_.capsule.center2 + position_,
            def_.capsule.radius};
}

MoveResult CharacterMover::move(const World& world, Vec2 displacement) {
    if (!isWithinHuge(displacement) || !isWithinHuge(position_ + displacement)) {
        core::throwError("physics::CharacterMover::move()",
                         "displacement must be finite and keep the mover within kHuge, got " +
                             core::formatVector(displacement));
    }
    const detail::MoverQuery query{&world,       def_.capsule,       def_.skin,
                                   def_.filter,  def_.ignoreBody,    def_.up,
                                   cosMaxSlope_, &def_.contactFilter};
    const Vec2 up = def_.up;
    // Surfaces this close count as touched (for the solver and for the contacts reported).
    const float reach = def_.skin + std::max(def_.skin, kLinearSlop);
    const Vec2 start = position_;
    const Vec2 target = position_ + displacement;
    MoveResult result;
    float budget = def_.maxPushOut;

    for (int pass = 0; pass < kMaxMoverPasses; ++pass) {
        result.passes = pass + 1;
        detail::collideMover(query, position_, reach, planes_, candidates_);
        // Static planes are solved last: when the planes cannot all be met (a platform pressing
        // the mover onto the floor) the answer meets theirs, and the mover is never pushed into
        // the level.
        std::stable_partition(planes_.begin(), planes_.end(), [&](const MoverContact& plane) {
            return world.bodyType(plane.body) != BodyType::Static;
        });
        constraints_.clear();
        float used = 0.0f;
        for (const MoverContact& plane : planes_) {
            detail::MoverConstraint c;
            c.normal = plane.normal;
            // Keep `skin` clear; an overlap is left by at most the push-out budget. A dynamic
            // body only blocks (no deeper): resting on the mover's head it must not press the
            // mover into the floor.
            c.need = std::min(def_.skin - plane.separation, budget);
            if (world.bodyType(plane.body) == BodyType::Dynamic) {
                c.need = std::min(c.need, 0.0f);
            }
            used = std::max(used, c.need);
            // Ground lifts the mover straight up (it does not slide down a slope it stands on and
            // keeps its speed along one it walks up); a slope too steep to stand on pushes
            // sideways (it cannot be climbed); walls and ceilings push along their normal.
            const float facing = dot(plane.normal, up);
            c.direction = plane.normal;
            if (plane.surface == MoverSurface::Ground) {
                c.direction = up;
            } else if (facing > 0.0f) {
                const Vec2 side = plane.normal - facing * up;
                if (length(side) > kMinHorizontal) {
                    c.direction = normalize(side);
                }
            }
            constraints_.push_back(c);
        }
        budget -= used;
        result.pushedOut += used;
        detail::PlaneSolution solution = detail::solvePlanes(target - position_, constraints_);
        if (!solution.converged) {
            // Pushes along different directions can fight (a V between two steep slopes): the
            // normals always agree on an answer.
            for (detail::MoverConstraint& c : constraints_) {
                c.direction = c.normal;
            }
            solution = detail::solvePlanes(target - position_, constraints_);
        }
        const Vec2 delta = solution.delta;
        if (lengthSquared(delta) < kStill * kStill) {
            break;
        }
        const float fraction = detail::castMover(query, position_, delta, candidates_);
        position_ += fraction * delta;
        if (fraction >= 1.0f) {
            break;
        }
    }

    const auto findContacts = [&](Vec2 at) {
        detail::collideMover(query, at, reach, contacts_, candidates_);
        bool ground = false;
        for (const MoverContact& contact : contacts_) {
            ground = ground || contact.surface == MoverSurface::Ground;
        }
        return ground;
    };
    bool grounded = findContacts(position_);
    if (!grounded && last_.grounded && def_.groundSnapDistance > 0.0f &&
        dot(displacement, up) <= 0.0f) {
        // Down a slope or a step: pull the mover onto ground just below, if there is some.
        const Vec2 down = -def_.groundSnapDistance * up;
        const float fraction = detail::castMover(query, position_, down, candidates_);
        if (fraction < 1.0f) {
            const Vec2 snapped = position_ + fraction * down;
            if (findContacts(snapped)) {
                position_ = snapped;
                grounded = true;
            } else {
                findContacts(position_);
            }
        }
    }

    result.position = position_;
    result.translation = position_ - start;
    result.grounded = grounded;
    float bestFacing = -2.0f;
    for (const MoverContact& contact : contacts_) {
        const float facing = dot(contact.normal, up);
        if (contact.surface == MoverSurface::Ground && facing > bestFacing) {
            bestFacing = facing;
            result.groundNormal = contact.normal;
            result.groundPoint = contact.point;
            result.groundShape = contact.shape;
            result.groundBody = contact.body;
        } else if (contact.surface == MoverSurface::Wall && !result.touchingWall) {
            result.touchingWall = true;
            result.wallNormal = contact.normal;
        } else if (contact.surface == MoverSurface::Ceiling && !result.touchingCeiling) {
            result.touchingCeiling = true;
            result.ceilingNormal = contact.normal;
        }
    }
    if (grounded) {
        result.groundVelocity =
            world.linearVelocityAtWorldPoint(result.groundBody, result.groundPoint);
    }
    last_ = result;
    return result;
}

Vec2 CharacterMover::clipVelocity(Vec2 velocity) const {
    for (const MoverContact& contact : contacts_) {
        if (contact.surface == MoverSurface::Ground) {
            const float along = dot(velocity, def_.up);
            if (along < 0.0f) {
                velocity -= along * def_.up;
            }
        } else {
            const float into = dot(velocity, contact.normal);
            if (into < 0.0f) {
                velocity -= into * contact.normal;
            }
        }
    }
    return velocity;
}

} // namespace e2d::physics
