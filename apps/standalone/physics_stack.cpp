// SPDX-License-Identifier: MIT
// e2d::physics alone: no window, no engine, just a World. A ball is thrown at a stack of three
// boxes; the program reports the collisions, then finds what is left standing with a ray cast.
// Links e2d::physics only. Exits 1 if the throw did not knock the top box off the stack.
#include <e2d/physics/world.hpp>

#include <cstdio>

int main() {
    using namespace e2d::physics;

    // Initialisation: a world in metres, kilograms and seconds, and its bodies.
    World world{WorldDef{.gravity = {0.0f, -9.81f}}};
    // A body is static unless told otherwise; makeBox takes half-extents: 20 m x 1 m, top at 0.5.
    const BodyId ground = world.createBody({});
    world.createShape(ground, {}, makeBox(10.0f, 0.5f));
    BodyId boxes[3];
    for (int i = 0; i < 3; ++i) { // three 1 m boxes, one on another
        boxes[i] = world.createBody(
            {.type = BodyType::Dynamic, .position = {4.0f, 1.0f + static_cast<float>(i)}});
        world.createShape(boxes[i], {.density = 1.0f, .friction = 0.6f}, makeBox(0.5f, 0.5f));
    }
    // A ball thrown at the top box; isBullet: swept against the boxes, never through them.
    const BodyId ball = world.createBody({.type = BodyType::Dynamic,
                                          .position = {-2.0f, 3.2f},
                                          .linearVelocity = {12.0f, 2.5f},
                                          .isBullet = true});
    const ShapeId ballShape =
        world.createShape(ball, {.density = 1.0f}, Circle{{0.0f, 0.0f}, 0.3f});

    // The loop: fixed steps of 1/60 s; events are read after each step, as arrays.
    for (int frame = 0; frame < 180; ++frame) {
        world.step(1.0f / 60.0f);
        for (const ContactBeginTouchEvent& e : world.contactBeginEvents()) {
            if (e.shapeA == ballShape || e.shapeB == ballShape) {
                std::printf("%.2f s: the ball hits a shape\n", (frame + 1) / 60.0);
            }
        }
    }

    // Queries: cast a ray down over the stack; the first thing it meets is the top of what stands.
    const std::optional<RayResult> hit = world.castRayClosest({4.0f, 10.0f}, {0.0f, -10.0f});
    const float top = hit ? hit->point.y : 0.0f;
    std::printf("the stack's top is at y = %.2f m (3.50 before the throw)\n", top);
    std::printf("the top box is at x = %.2f m\n", world.transform(boxes[2]).p.x);

    // Shutdown: the World frees everything it made when it goes out of scope.
    const bool knockedOff = top < 3.0f && world.transform(boxes[2]).p.x > 4.5f;
    return knockedOff ? 0 : 1;
}
