// SPDX-License-Identifier: MIT
// The README's "Physics in a dozen lines", line for line (printf replaced by recording what it
// prints), so the example keeps compiling and saying what it says.
#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

TEST(ReadmeExample, TheBallBouncesWhenAndWhereTheReadmeSays) {
    std::vector<double> bounces;
    float finalY = 0.0f;
    float cordForce = 0.0f;
    float lampY = 0.0f;
    {
        using namespace e2d::physics;
        World world{WorldDef{.gravity = {0.0f, -10.0f}}};
        BodyId ground = world.createBody({}); // static unless told otherwise
        world.createShape(ground, {}, makeBox(20.0f, 0.5f));
        BodyId ball = world.createBody({.type = BodyType::Dynamic, .position = {0.0f, 4.0f}});
        ShapeId ballShape =
            world.createShape(ball, {.restitution = 0.5f}, Circle{{0.0f, 0.0f}, 0.25f});
        BodyId lamp = world.createBody({.type = BodyType::Dynamic, .position = {3.0f, 3.0f}});
        world.createShape(lamp, {}, Circle{{0.0f, 0.0f}, 0.2f});
        JointId cord = world.createJoint(RevoluteJointDef{// a hinge 1 m above the lamp
                                                          .bodyA = ground,
                                                          .bodyB = lamp,
                                                          .localAnchorA = {3.0f, 4.0f},
                                                          .localAnchorB = {0.0f, 1.0f}});
        for (int frame = 0; frame < 120; ++frame) {
            world.step(1.0f / 60.0f); // a fixed step, at most kMaxTimeStep (0.25 s)
            for (const ContactBeginTouchEvent& e : world.contactBeginEvents()) {
                if (e.shapeA == ballShape || e.shapeB == ballShape) {
                    bounces.push_back((frame + 1) / 60.0); // printf("bounce at %.2f s\n", ...)
                }
            }
        }
        finalY = world.transform(ball).p.y;           // printf("ball at y = %.2f m\n", ...)
        cordForce = world.jointReactionForce(cord).y; // printf("the cord holds %.2f N\n", ...)
        lampY = world.transform(lamp).p.y;
    }
    // From first principles: the ball's bottom falls 4 - 0.25 - 0.5 = 3.25 m, t = sqrt(2h/g);
    // it leaves at half the impact speed and is back after 2 * v / g (a contact is found up to
    // a frame early, speculatively).
    const double fall = std::sqrt(2.0 * 3.25 / 10.0);
    ASSERT_EQ(bounces.size(), 2u);
    EXPECT_NEAR(bounces[0], fall, 1.5 / 60.0);
    EXPECT_NEAR(bounces[1], fall + 2.0 * 0.5 * 10.0 * fall / 10.0, 2.5 / 60.0);
    // The README's comments: 0.82 s, then 1.63 s.
    EXPECT_NEAR(bounces[0], 0.82, 0.005);
    EXPECT_NEAR(bounces[1], 1.63, 0.005);
    // After 2 s the third bounce has not come yet (1.63 + 0.4 s): the ball is in the air.
    EXPECT_GT(finalY, 0.75f);
    // The lamp (a disc of 0.2 m at density 1) hangs still from its hinge, which holds its
    // weight: pi 0.2^2 kg times 10 m/s^2 = 1.26 N.
    const double weight = 3.14159265358979 * 0.2 * 0.2 * 10.0;
    EXPECT_NEAR(cordForce, weight, 0.01 * weight);
    EXPECT_NEAR(lampY, 3.0f, 1e-3f);
}

} // namespace
