// SPDX-License-Identifier: MIT
// World's joint functions: creation from defs (validated), destruction, the per-body lists,
// collideConnected, getters and setters.
#include <e2d/physics/world.hpp>

#include "joint_def_check.hpp"
#include "world_check.hpp"
#include "world_impl.hpp"

#include <string>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

namespace {

constexpr const char* kCreate = "createJoint";

// "revolute def.hertz": the def's type and field.
std::string field(JointType type, const char* name) {
    return std::string(jointTypeName(type)) + " def." + name;
}

void finite(JointType t, const char* name, float x) {
    check::requireFinite(kCreate, field(t, name).c_str(), x);
}
void finite(JointType t, const char* name, Vec2 x) {
    check::requireFinite(kCreate, field(t, name).c_str(), x);
}
void nonNegative(JointType t, const char* name, float x) {
    check::requireNonNegative(kCreate, field(t, name).c_str(), x);
}
void ordered(JointType t, const char* lowerName, float lower, const char* upperName, float upper) {
    finite(t, lowerName, lower);
    finite(t, upperName, upper);
    if (!(lower <= upper)) {
        check::fail(kCreate, field(t, lowerName) + " must be <= def." + upperName + ", got " +
                                 check::text(lower) + " > " + check::text(upper));
    }
}
void unitAxis(JointType t, Vec2 axis) {
    finite(t, "localAxisA", axis);
    if (!(lengthSquared(axis) > 1e-12f)) {
        check::fail(kCreate,
                    field(t, "localAxisA") + " must be non-zero, got " + check::text(axis));
    }
}

// The common fields of every def.
template <typename Def>
void common(detail::Joint& j, const Def& d) {
    j.collideConnected = d.collideConnected;
    j.userData = d.userData;
}

// Validates `def` and fills the joint's definition fields.
detail::Joint jointFrom(const JointDef& def) {
    detail::Joint j;
    j.type = jointTypeOf(def);
    const JointType t = j.type;
    std::visit(
        [&](const auto& d) {
            using D = std::decay_t<decltype(d)>;
            common(j, d);
            if constexpr (std::is_same_v<D, DistanceJointDef>) {
                finite(t, "localAnchorA", d.localAnchorA);
                finite(t, "localAnchorB", d.localAnchorB);
                finite(t, "length", d.length);
                if (!(d.length >= kLinearSlop)) {
                    check::fail(kCreate, field(t, "length") + " must be >= kLinearSlop (" +
                                             check::text(kLinearSlop) + " m), got " +
                                             check::text(d.length));
                }
                nonNegative(t, "hertz", d.hertz);
                nonNegative(t, "dampingRatio", d.dampingRatio);
                nonNegative(t, "minLength", d.minLength);
                ordered(t, "minLength", d.minLength, "maxLength", d.maxLength);
                nonNegative(t, "maxMotorForce", d.maxMotorForce);
                finite(t, "motorSpeed", d.motorSpeed);
                j.localAnchorA = d.localAnchorA;
                j.localAnchorB = d.localAnchorB;
                j.length = d.length;
                j.enableSpring = d.enableSpring;
                j.hertz = d.hertz;
                j.dampingRatio = d.dampingRatio;
                j.enableLimit = d.enableLimit;
                j.minLength = d.minLength;
                j.maxLength = d.maxLength;
                j.enableMotor = d.enableMotor;
                j.maxMotorForce = d.maxMotorForce;
                j.motorSpeed = d.motorSpeed;
            } else if constexpr (std::is_same_v<D, MotorJointDef>) {
                finite(t, "linearOffset", d.linearOffset);
                finite(t, "angularOffset", d.angularOffset);
                nonNegative(t, "maxForce", d.maxForce);
                nonNegative(t, "maxTorque", d.maxTorque);
                if (!(isFinite(d.correctionFactor) && d.correctionFactor >= 0.0f &&
                      d.correctionFactor <= 1.0f)) {
                    check::fail(kCreate, field(t, "correctionFactor") + " must be in [0, 1], got " +
                                             check::text(d.correctionFactor));
                }
                j.localAnchorA = d.linearOffset;
                j.referenceAngle = d.angularOffset;
                j.maxMotorForce = d.maxForce;
                j.maxTorque = d.maxTorque;
                j.correctionFactor = d.correctionFactor;
            } else if constexpr (std::is_same_v<D, MouseJointDef>) {
                check::requirePosition(kCreate, field(t, "target").c_str(), d.target);
                finite(t, "localAnchorB", d.localAnchorB);
                finite(t, "hertz", d.hertz);
                if (!(d.hertz > 0.0f)) {
                    check::fail(kCreate,
                                field(t, "hertz") + " must be > 0, got " + check::text(d.hertz));
                }
                nonNegative(t, "dampingRatio", d.dampingRatio);
                nonNegative(t, "maxForce", d.maxForce);
                j.target = d.target;
                j.localAnchorB = d.localAnchorB;
                j.hertz = d.hertz;
                j.dampingRatio = d.dampingRatio;
                j.maxMotorForce = d.maxForce;
            } else if constexpr (std::is_same_v<D, PrismaticJointDef> ||
                                 std::is_same_v<D, WheelJointDef>) {
                finite(t, "localAnchorA", d.localAnchorA);
                finite(t, "localAnchorB", d.localAnchorB);
                unitAxis(t, d.localAxisA);
                nonNegative(t, "hertz", d.hertz);
                nonNegative(t, "dampingRatio", d.dampingRatio);
                ordered(t, "lowerTranslation", d.lowerTranslation, "upperTranslation",
                        d.upperTranslation);
                finite(t, "motorSpeed", d.motorSpeed);
                j.localAnchorA = d.localAnchorA;
                j.localAnchorB = d.localAnchorB;
                j.localAxisA = normalize(d.localAxisA);
                j.enableSpring = d.enableSpring;
                j.hertz = d.hertz;
                j.dampingRatio = d.dampingRatio;
                j.enableLimit = d.enableLimit;
                j.lower = d.lowerTranslation;
                j.upper = d.upperTranslation;
                j.enableMotor = d.enableMotor;
                j.motorSpeed = d.motorSpeed;
                if constexpr (std::is_same_v<D, PrismaticJointDef>) {
                    finite(t, "referenceAngle", d.referenceAngle);
                    nonNegative(t, "maxMotorForce", d.maxMotorForce);
                    j.referenceAngle = d.referenceAngle;
                    j.maxMotorForce = d.maxMotorForce;
                } else {
                    nonNegative(t, "maxMotorTorque", d.maxMotorTorque);
                    j.maxMotorForce = d.maxMotorTorque;
                }
            } else if constexpr (std::is_same_v<D, RevoluteJointDef>) {
                finite(t, "localAnchorA", d.localAnchorA);
                finite(t, "localAnchorB", d.localAnchorB);
                finite(t, "referenceAngle", d.referenceAngle);
                nonNegative(t, "hertz", d.hertz);
                nonNegative(t, "dampingRatio", d.dampingRatio);
                ordered(t, "lowerAngle", d.lowerAngle, "upperAngle", d.upperAngle);
                nonNegative(t, "maxMotorTorque", d.maxMotorTorque);
                finite(t, "motorSpeed", d.motorSpeed);
                j.localAnchorA = d.localAnchorA;
                j.localAnchorB = d.localAnchorB;
                j.referenceAngle = d.referenceAngle;
                j.enableSpring = d.enableSpring;
                j.hertz = d.hertz;
                j.dampingRatio = d.dampingRatio;
                j.enableLimit = d.enableLimit;
                j.lower = d.lowerAngle;
                j.upper = d.upperAngle;
                j.enableMotor = d.enableMotor;
                j.maxMotorForce = d.maxMotorTorque;
                j.motorSpeed = d.motorSpeed;
            } else {
                static_assert(std::is_same_v<D, WeldJointDef>);
                finite(t, "localAnchorA", d.localAnchorA);
                finite(t, "localAnchorB", d.localAnchorB);
                finite(t, "referenceAngle", d.referenceAngle);
                nonNegative(t, "linearHertz", d.linearHertz);
                nonNegative(t, "angularHertz", d.angularHertz);
                nonNegative(t, "linearDampingRatio", d.linearDampingRatio);
                nonNegative(t, "angularDampingRatio", d.angularDampingRatio);
                j.localAnchorA = d.localAnchorA;
                j.localAnchorB = d.localAnchorB;
                j.referenceAngle = d.referenceAngle;
                j.hertz = d.linearHertz;
                j.dampingRatio = d.linearDampingRatio;
                j.angularHertz = d.angularHertz;
                j.angularDampingRatio = d.angularDampingRatio;
            }
        },
        def);
    return j;
}

std::pair<BodyId, BodyId> bodiesOf(const JointDef& def) {
    return std::visit(
        [](const auto& d) {
            return std::pair<BodyId, BodyId>{d.bodyA, d.bodyB};
        },
        def);
}

} // namespace

void detail::validateJointDef(const JointDef& def) { (void)jointFrom(def); }

JointType jointTypeOf(const JointDef& def) { return static_cast<JointType>(def.index()); }

const char* jointTypeName(JointType type) {
    switch (type) {
    case JointType::Distance:
        return "distance";
    case JointType::Motor:
        return "motor";
    case JointType::Mouse:
        return "mouse";
    case JointType::Prismatic:
        return "prismatic";
    case JointType::Revolute:
        return "revolute";
    case JointType::Weld:
        return "weld";
    case JointType::Wheel:
        return "wheel";
    }
    return "unknown";
}

bool World::Impl::jointBlocksCollision(int bodyA, int bodyB) const {
    // Walk the shorter-looking list: the one of the body with fewer joints is unknown, so A's.
    for (int ji = body(bodyA).jointHead; ji != kNullIndex;) {
        const detail::Joint& j = joint(ji);
        const int side = j.bodyA == bodyA ? 0 : 1;
        const int other = side == 0 ? j.bodyB : j.bodyA;
        if (other == bodyB && !j.collideConnected) {
            return true;
        }
        ji = j.next[side];
    }
    return false;
}

void World::Impl::destroyJointAt(int jointIndex) {
    detail::Joint& j = joint(jointIndex);
    for (int side = 0; side < 2; ++side) {
        const int bodyIndex = side == 0 ? j.bodyA : j.bodyB;
        if (j.prev[side] != kNullIndex) {
            detail::Joint& p = joint(j.prev[side]);
            p.next[p.bodyA == bodyIndex ? 0 : 1] = j.next[side];
        } else {
            body(bodyIndex).jointHead = j.next[side];
        }
        if (j.next[side] != kNullIndex) {
            detail::Joint& n = joint(j.next[side]);
            n.prev[n.bodyA == bodyIndex ? 0 : 1] = j.prev[side];
        }
    }
    const int bodyA = j.bodyA;
    const int bodyB = j.bodyB;
    const bool blocked = !j.collideConnected;
    j.alive = false;
    j.generation = core::nextGeneration(j.generation);
    j.bodyA = j.bodyB = kNullIndex;
    jointIds.release(jointIndex);
    wakeBody(bodyA);
    wakeBody(bodyB);
    if (blocked) {
        // Their shapes may pair again: have the broad phase look around A's.
        for (int si = body(bodyA).headShape; si != kNullIndex; si = shape(si).nextShape) {
            if (shape(si).proxyKey != kNullIndex) {
                broadPhase.bufferMove(shape(si).proxyKey);
            }
        }
    }
}

JointId World::createJoint(const JointDef& def) {
    impl_->requireUnlocked(kCreate);
    Impl& w = *impl_;
    const auto [idA, idB] = bodiesOf(def);
    const int bodyA = w.require(idA, kCreate);
    const int bodyB = w.require(idB, kCreate);
    if (bodyA == bodyB) {
        check::fail(kCreate, field(jointTypeOf(def), "bodyA") +
                                 " and def.bodyB must differ, got the same body");
    }
    if (w.body(bodyA).type != BodyType::Dynamic && w.body(bodyB).type != BodyType::Dynamic) {
        check::fail(kCreate,
                    field(jointTypeOf(def), "bodyA") +
                        " or def.bodyB must be dynamic, got two bodies that no force moves");
    }
    detail::Joint made = jointFrom(def);
    made.bodyA = bodyA;
    made.bodyB = bodyB;
    const detail::Body& a = w.body(bodyA);
    const detail::Body& b = w.body(bodyB);
    made.angleRotation = invMulRot(a.transform.q, b.transform.q);
    made.angle = detail::wrapAngle(made.angleRotation.angle() - made.referenceAngle);
    if (made.type == JointType::Motor) {
        made.localAnchorB = {0.0f, 0.0f};
    }

    const int index = w.jointIds.allocate();
    if (index == static_cast<int>(w.joints.size())) {
        w.joints.emplace_back();
    }
    detail::Joint& j = w.joint(index);
    made.generation = j.generation;
    made.alive = true;
    j = made;
    for (int side = 0; side < 2; ++side) {
        const int bodyIndex = side == 0 ? bodyA : bodyB;
        detail::Body& body = w.body(bodyIndex);
        j.prev[side] = kNullIndex;
        j.next[side] = body.jointHead;
        if (body.jointHead != kNullIndex) {
            detail::Joint& head = w.joint(body.jointHead);
            head.prev[head.bodyA == bodyIndex ? 0 : 1] = index;
        }
        body.jointHead = index;
    }
    if (!j.collideConnected) {
        // A contact between the two ends now (end event with the next step's).
        int ci = w.body(bodyA).motion.contactHead;
        while (ci != kNullIndex) {
            const detail::Contact& c = w.sim.contacts[static_cast<std::size_t>(ci)];
            const detail::ContactLinks& l = w.sim.contactLinks[static_cast<std::size_t>(ci)];
            const int side = c.bodyA == bodyA ? 0 : 1;
            const int next = l.next[side];
            if ((side == 0 ? c.bodyB : c.bodyA) == bodyB) {
                w.broadPhase.removePair(static_cast<std::uint64_t>(l.shapeA),
                                        static_cast<std::uint64_t>(l.shapeB));
                w.destroyContact(ci, true);
            }
            ci = next;
        }
    }
    w.wakeBody(bodyA);
    w.wakeBody(bodyB);
    return w.jointId(index);
}

void World::destroyJoint(JointId id) {
    impl_->requireUnlocked("destroyJoint");
    impl_->destroyJointAt(impl_->require(id, "destroyJoint"));
}

bool World::isValid(JointId id) const { return impl_->find(id) != kNullIndex; }

JointType World::jointType(JointId id) const {
    return impl_->joint(impl_->require(id, "jointType")).type;
}

BodyId World::jointBodyA(JointId id) const {
    return impl_->bodyId(impl_->joint(impl_->require(id, "jointBodyA")).bodyA);
}

BodyId World::jointBodyB(JointId id) const {
    return impl_->bodyId(impl_->joint(impl_->require(id, "jointBodyB")).bodyB);
}

std::vector<JointId> World::bodyJoints(BodyId id) const {
    const Impl& w = *impl_;
    const int bodyIndex = w.require(id, "bodyJoints");
    std::vector<JointId> out;
    for (int ji = w.body(bodyIndex).jointHead; ji != kNullIndex;) {
        out.push_back(w.jointId(ji));
        const detail::Joint& j = w.joint(ji);
        ji = j.next[j.bodyA == bodyIndex ? 0 : 1];
    }
    return out;
}

std::uint64_t World::jointUserData(JointId id) const {
    return impl_->joint(impl_->require(id, "jointUserData")).userData;
}

void World::setJointUserData(JointId id, std::uint64_t userData) {
    impl_->joint(impl_->require(id, "setJointUserData")).userData = userData;
}

Vec2 World::jointAnchorA(JointId id) const {
    const Impl& w = *impl_;
    const detail::Joint& j = w.joint(w.require(id, "jointAnchorA"));
    return j.type == JointType::Mouse ? j.target
                                      : transformPoint(w.body(j.bodyA).transform, j.localAnchorA);
}

Vec2 World::jointAnchorB(JointId id) const {
    const Impl& w = *impl_;
    const detail::Joint& j = w.joint(w.require(id, "jointAnchorB"));
    return transformPoint(w.body(j.bodyB).transform, j.localAnchorB);
}

Vec2 World::jointReactionForce(JointId id) const {
    return impl_->joint(impl_->require(id, "jointReactionForce")).reactionForce;
}

float World::jointReactionTorque(JointId id) const {
    return impl_->joint(impl_->require(id, "jointReactionTorque")).reactionTorque;
}

float World::jointValue(JointId id) const {
    const Impl& w = *impl_;
    const detail::Joint& j = w.joint(w.require(id, "jointValue"));
    const Transform& ta = w.body(j.bodyA).transform;
    const Transform& tb = w.body(j.bodyB).transform;
    const Vec2 pA = transformPoint(ta, j.localAnchorA);
    const Vec2 pB = transformPoint(tb, j.localAnchorB);
    switch (j.type) {
    case JointType::Revolute: {
        float now = detail::wrapAngle(detail::relativeAngle(ta.q, tb.q) - j.referenceAngle);
        return j.angle + detail::wrapAngle(now - j.angle);
    }
    case JointType::Prismatic:
    case JointType::Wheel:
        return dot(rotate(ta.q, j.localAxisA), pB - pA);
    case JointType::Distance:
        return distance(pA, pB);
    default:
        check::fail("jointValue", std::string("a ") + jointTypeName(j.type) +
                                      " joint has no angle, translation or length");
    }
}

namespace {

// The joint at `id` if its type is one of `types`, else an error naming the function.
template <typename Impl>
detail::Joint& typed(Impl& w, JointId id, const char* function,
                     std::initializer_list<JointType> types) {
    detail::Joint& j = w.joint(w.require(id, function));
    for (JointType t : types) {
        if (j.type == t) {
            return j;
        }
    }
    check::fail(function, std::string("not supported by a ") + jointTypeName(j.type) + " joint");
}

template <typename Impl>
void wakeEnds(Impl& w, const detail::Joint& j) {
    w.wakeBody(j.bodyA);
    w.wakeBody(j.bodyB);
}

constexpr std::initializer_list<JointType> kMotorTypes = {JointType::Distance, JointType::Prismatic,
                                                          JointType::Revolute, JointType::Wheel};

} // namespace

void World::enableJointMotor(JointId id, bool enable) {
    detail::Joint& j = typed(*impl_, id, "enableJointMotor", kMotorTypes);
    j.enableMotor = enable;
    wakeEnds(*impl_, j);
}

void World::setJointMotorSpeed(JointId id, float speed) {
    check::requireFinite("setJointMotorSpeed", "speed", speed);
    detail::Joint& j = typed(*impl_, id, "setJointMotorSpeed", kMotorTypes);
    j.motorSpeed = speed;
    wakeEnds(*impl_, j);
}

void World::setJointMaxMotorForce(JointId id, float force) {
    check::requireNonNegative("setJointMaxMotorForce", "force", force);
    detail::Joint& j = typed(*impl_, id, "setJointMaxMotorForce",
                             {JointType::Distance, JointType::Prismatic, JointType::Revolute,
                              JointType::Wheel, JointType::Mouse, JointType::Motor});
    j.maxMotorForce = force;
    wakeEnds(*impl_, j);
}

void World::enableJointLimit(JointId id, bool enable) {
    detail::Joint& j = typed(*impl_, id, "enableJointLimit", kMotorTypes);
    j.enableLimit = enable;
    wakeEnds(*impl_, j);
}

void World::setJointLimits(JointId id, float lower, float upper) {
    const char* fn = "setJointLimits";
    check::requireFinite(fn, "lower", lower);
    check::requireFinite(fn, "upper", upper);
    if (!(lower <= upper)) {
        check::fail(fn, "lower must be <= upper, got " + check::text(lower) + " > " +
                            check::text(upper));
    }
    detail::Joint& j = typed(*impl_, id, fn, kMotorTypes);
    if (j.type == JointType::Distance) {
        check::requireNonNegative(fn, "lower", lower);
        j.minLength = lower;
        j.maxLength = upper;
    } else {
        j.lower = lower;
        j.upper = upper;
    }
    wakeEnds(*impl_, j);
}

void World::setJointSpring(JointId id, float hertz, float dampingRatio) {
    const char* fn = "setJointSpring";
    check::requireNonNegative(fn, "hertz", hertz);
    check::requireNonNegative(fn, "dampingRatio", dampingRatio);
    detail::Joint& j = typed(*impl_, id, fn,
                             {JointType::Distance, JointType::Prismatic, JointType::Revolute,
                              JointType::Wheel, JointType::Mouse, JointType::Weld});
    if (j.type == JointType::Mouse && !(hertz > 0.0f)) {
        check::fail(fn, "a mouse joint's hertz must be > 0, got " + check::text(hertz));
    }
    j.hertz = hertz;
    j.dampingRatio = dampingRatio;
    if (j.type == JointType::Weld) {
        j.angularHertz = hertz;
        j.angularDampingRatio = dampingRatio;
    } else if (j.type != JointType::Mouse) {
        j.enableSpring = hertz > 0.0f;
    }
    wakeEnds(*impl_, j);
}

void World::setMouseJointTarget(JointId id, Vec2 target) {
    check::requirePosition("setMouseJointTarget", "target", target);
    detail::Joint& j = typed(*impl_, id, "setMouseJointTarget", {JointType::Mouse});
    j.target = target;
    impl_->wakeBody(j.bodyB);
}

void World::setMotorJointOffsets(JointId id, Vec2 linearOffset, float angularOffset) {
    check::requireFinite("setMotorJointOffsets", "linearOffset", linearOffset);
    check::requireFinite("setMotorJointOffsets", "angularOffset", angularOffset);
    detail::Joint& j = typed(*impl_, id, "setMotorJointOffsets", {JointType::Motor});
    j.localAnchorA = linearOffset;
    j.referenceAngle = angularOffset;
    wakeEnds(*impl_, j);
}

int World::jointCount() const { return impl_->jointIds.count(); }

std::vector<JointDebugData> World::jointDebugData() const {
    const Impl& w = *impl_;
    std::vector<JointDebugData> out;
    out.reserve(static_cast<std::size_t>(w.jointIds.count()));
    for (std::size_t i = 0; i < w.joints.size(); ++i) {
        const detail::Joint& j = w.joints[i];
        if (!j.alive) {
            continue;
        }
        const Transform& ta = w.body(j.bodyA).transform;
        const Transform& tb = w.body(j.bodyB).transform;
        JointDebugData d;
        d.id = w.jointId(static_cast<int>(i));
        d.type = j.type;
        d.originA = ta.p;
        d.originB = tb.p;
        d.anchorA = j.type == JointType::Mouse ? j.target : transformPoint(ta, j.localAnchorA);
        d.anchorB = transformPoint(tb, j.localAnchorB);
        if (j.type == JointType::Prismatic || j.type == JointType::Wheel) {
            d.axis = rotate(ta.q, j.localAxisA);
        }
        if (j.enableLimit) {
            d.limitEnabled = true;
            d.lower = j.type == JointType::Distance ? j.minLength : j.lower;
            d.upper = j.type == JointType::Distance ? j.maxLength : j.upper;
        }
        out.push_back(d);
    }
    return out;
}

} // namespace e2d::physics
