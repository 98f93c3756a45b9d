// SPDX-License-Identifier: MIT
// SolverDef::jointSolver: the soft step's joint models. The default (Direct) holds limits
// inelastically, corrects a violated limit without speed and keeps chains, welds and heavy
// loads rigid; Soft is Box2D v3's model (soft rows, no position pass), for comparison.
#include "joint_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics::test {
namespace {

WorldDef modelDef(JointSolver model, Vec2 gravity = {0.0f, -10.0f}) {
    WorldDef def;
    def.gravity = gravity;
    def.solver.jointSolver = model;
    return def;
}

// A 1 kg door (1 x 0.05 m) hinged at its left end to a static post at the origin, limits
// [lower, upper] from where it starts; zero gravity.
struct Door {
    BodyId body;
    JointId hinge;
};
Door addDoor(World& world, float lower, float upper, float spin) {
    BodyId post = addStatic(world, {0.0f, 0.0f});
    BodyId door = addPlank(world, {0.5f, 0.0f}, 0.5f, 0.025f, 20.0f);
    world.setLinearVelocity(door, {0.0f, 0.5f * spin});
    world.setAngularVelocity(door, spin);
    RevoluteJointDef def;
    def.bodyA = post;
    def.bodyB = door;
    def.localAnchorB = {-0.5f, 0.0f};
    def.enableLimit = true;
    def.lowerAngle = lower;
    def.upperAngle = upper;
    return {door, world.createJoint(def)};
}

constexpr float kHalfPi = 0.5f * kPi;
constexpr float kDegree = kPi / 180.0f;

// A limit is inelastic: the door flung at 10 rad/s stops at 90 degrees and stays there. Box2D
// v3's model (Soft) hands the door back 14 % of its speed.
TEST(JointSolverModel, DoorFlungIntoItsLimitStopsDead) {
    for (JointSolver model : {JointSolver::Direct, JointSolver::GaussSeidel}) {
        World world(modelDef(model, {0.0f, 0.0f}));
        const Door door = addDoor(world, -kHalfPi, kHalfPi, 10.0f);
        float largest = 0.0f;
        for (int i = 0; i < 120; ++i) {
            world.step(kJointStep);
            largest = std::max(largest, world.jointValue(door.hinge));
        }
        EXPECT_LT(largest, kHalfPi + 2.0f * kDegree) << static_cast<int>(model);
        EXPECT_NEAR(world.jointValue(door.hinge), kHalfPi, 2.0f * kDegree)
            << static_cast<int>(model);
        EXPECT_NEAR(world.angularVelocity(door.body), 0.0f, 0.01f) << static_cast<int>(model);
    }
    World soft(modelDef(JointSolver::Soft, {0.0f, 0.0f}));
    const Door door = addDoor(soft, -kHalfPi, kHalfPi, 10.0f);
    run(soft, 2.0f);
    EXPECT_LT(soft.jointValue(door.hinge), kHalfPi - 10.0f * kDegree) << "the soft rows' rebound";
}

// A door started 30 degrees past its limit is pushed out by the position passes (at most 8
// degrees each, no velocity): it ends at the limit, at rest, never fast. Soft flings it.
TEST(JointSolverModel, ViolatedLimitIsCorrectedWithoutSpeed) {
    World world(modelDef(JointSolver::Direct, {0.0f, 0.0f}));
    const Door door = addDoor(world, 30.0f * kDegree, kHalfPi, 0.0f);
    float fastest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(kJointStep);
        fastest = std::max(fastest, std::abs(world.angularVelocity(door.body)));
    }
    EXPECT_NEAR(world.jointValue(door.hinge), 30.0f * kDegree, 2.0f * kDegree);
    EXPECT_LT(fastest, 0.01f);

    World soft(modelDef(JointSolver::Soft, {0.0f, 0.0f}));
    const Door flung = addDoor(soft, 30.0f * kDegree, kHalfPi, 0.0f);
    float softFastest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        soft.step(kJointStep);
        softFastest = std::max(softFastest, std::abs(soft.angularVelocity(flung.body)));
    }
    EXPECT_GT(softFastest, 1.0f);
}

// A chain of `links` planks (0.5 x 0.1 m) hanging from a static pivot, released horizontal, a
// ball of `ballMass` kg on its end: the largest joint gap over `seconds`.
float heavyChainGap(JointSolver model, int links, float ballMass, float seconds) {
    World world(modelDef(model));
    BodyId previous = addStatic(world, {0.0f, 20.0f});
    std::vector<BodyId> bodies;
    std::vector<JointId> joints;
    for (int k = 0; k < links; ++k) {
        BodyId link = addPlank(world, {0.25f + 0.5f * static_cast<float>(k), 20.0f}, 0.25f, 0.05f);
        RevoluteJointDef def;
        def.bodyA = previous;
        def.bodyB = link;
        def.localAnchorA = k == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.25f, 0.0f};
        def.localAnchorB = {-0.25f, 0.0f};
        joints.push_back(world.createJoint(def));
        previous = link;
    }
    BodyId ball = addDisc(world, {0.5f * static_cast<float>(links) + 0.25f, 20.0f}, 0.25f);
    world.setMassData(ball, {ballMass, {0.0f, 0.0f}, 0.5f * ballMass * 0.0625f});
    RevoluteJointDef last;
    last.bodyA = previous;
    last.bodyB = ball;
    last.localAnchorA = {0.25f, 0.0f};
    last.localAnchorB = {-0.25f, 0.0f};
    joints.push_back(world.createJoint(last));
    float worst = 0.0f;
    const int steps = static_cast<int>(seconds / kJointStep);
    for (int i = 0; i < steps; ++i) {
        world.step(kJointStep);
        for (JointId j : joints) {
            worst = std::max(worst, length(world.jointAnchorB(j) - world.jointAnchorA(j)));
        }
    }
    return worst;
}

// A 5 kg ball on ten 0.05 kg links (1:100) swinging down: the direct solve keeps every joint
// shut where the soft rows stretch like springs (about 4 cm each, see SolverDef::jointHertz).
TEST(JointSolverModel, HeavyBallOnALightChainKeepsItsLength) {
    const float direct = heavyChainGap(JointSolver::Direct, 10, 5.0f, 3.0f);
    const float soft = heavyChainGap(JointSolver::Soft, 10, 5.0f, 3.0f);
    EXPECT_LT(direct, 0.01f);
    EXPECT_GT(soft, 3.0f * direct);
}

// Eight 1 m planks welded end to end from a wall: the tip stays level (Soft sags it 1 m).
float cantileverTipDrop(JointSolver model) {
    World world(modelDef(model));
    BodyId previous = addStatic(world, {0.0f, 5.0f});
    BodyId tip{};
    for (int k = 0; k < 8; ++k) {
        tip = addPlank(world, {0.5f + static_cast<float>(k), 5.0f}, 0.5f, 0.05f);
        WeldJointDef def;
        def.bodyA = previous;
        def.bodyB = tip;
        def.localAnchorA = k == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.5f, 0.0f};
        def.localAnchorB = {-0.5f, 0.0f};
        world.createJoint(def);
        previous = tip;
    }
    run(world, 3.0f);
    return 5.0f - world.transform(tip).p.y;
}

TEST(JointSolverModel, WeldedCantileverDoesNotSag) {
    EXPECT_LT(cantileverTipDrop(JointSolver::Direct), 0.01f);
    EXPECT_GT(cantileverTipDrop(JointSolver::Soft), 0.05f);
}

// An arm of `links` planks (0.5 x 0.1 m, density 1) held out level from a wall, every hinge
// limited to +-3 degrees: under gravity each comes to rest on its lower limit, the tip link at
// -3 degrees per hinge. The tip's largest and final turn, and the largest joint gap.
struct ArmResult {
    float largestTurn = 0.0f;
    float finalTurn = 0.0f;
    float worstGap = 0.0f;
};
ArmResult limitedArm(int links, float seconds) {
    World world(modelDef(JointSolver::Direct));
    BodyId previous = addStatic(world, {0.0f, 10.0f});
    std::vector<JointId> joints;
    BodyId tip{};
    for (int k = 0; k < links; ++k) {
        tip = addPlank(world, {0.25f + 0.5f * static_cast<float>(k), 10.0f}, 0.25f, 0.05f);
        RevoluteJointDef def;
        def.bodyA = previous;
        def.bodyB = tip;
        def.localAnchorA = k == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.25f, 0.0f};
        def.localAnchorB = {-0.25f, 0.0f};
        def.enableLimit = true;
        def.lowerAngle = -3.0f * kDegree;
        def.upperAngle = 3.0f * kDegree;
        joints.push_back(world.createJoint(def));
        previous = tip;
    }
    ArmResult result;
    const int steps = static_cast<int>(seconds / kJointStep);
    for (int i = 0; i < steps; ++i) {
        world.step(kJointStep);
        result.finalTurn = -world.transform(tip).q.angle();
        result.largestTurn = std::max(result.largestTurn, result.finalTurn);
        for (JointId j : joints) {
            result.worstGap =
                std::max(result.worstGap, length(world.jointAnchorB(j) - world.jointAnchorA(j)));
        }
    }
    return result;
}

// Stacked limits hold: the root hinge carries the whole arm against a tip link hundreds of
// times lighter, and every limit is reached at once. The direct solve treats the reached limits
// as a complementarity problem on top of the hinges' points (no limit released for good, none
// pulling), so the tip passes its resting turn by less than 0.1 degree per hinge and ends on it.
// (An active set that only released limits, never taking one back, let this arm's tip swing
// 5 degrees past and opened its joints 3.6 cm.)
TEST(JointSolverModel, StackedLimitsHoldALimitedArm) {
    constexpr int kLinks = 12;
    const ArmResult arm = limitedArm(kLinks, 2.0f);
    const float rest = 3.0f * kDegree * static_cast<float>(kLinks);
    EXPECT_LT(arm.largestTurn, rest + 0.1f * kDegree * static_cast<float>(kLinks));
    EXPECT_NEAR(arm.finalTurn, rest, 0.1f * kDegree * static_cast<float>(kLinks));
    EXPECT_LT(arm.worstGap, 0.005f);
}

// The same world stepped twice gives the same bits (the factorisation's order is fixed).
TEST(JointSolverModel, DirectSolveIsDeterministic) {
    EXPECT_EQ(heavyChainGap(JointSolver::Direct, 10, 5.0f, 1.0f),
              heavyChainGap(JointSolver::Direct, 10, 5.0f, 1.0f));
}

TEST(JointSolverModel, BadSettingsNameTheField) {
    WorldDef def;
    def.solver.jointPositionIterations = -1;
    E2D_EXPECT_ERROR(
        World{def},
        "physics::World::World(): def.solver.jointPositionIterations must be in [0, 256], got -1");
    def = {};
    def.solver.jointSolver = static_cast<JointSolver>(7);
    E2D_EXPECT_ERROR(World{def}, "physics::World::World(): def.solver.jointSolver must be Soft, "
                                 "GaussSeidel or Direct, got 7");
}

} // namespace
} // namespace e2d::physics::test
