// SPDX-License-Identifier: MIT
// Errors at the seam between game objects and physics name the object (its name, else its tag,
// else its id), the component and the value, in the world units the user gave.
#include "component_scene.hpp"

#include <e2d/core/error.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>

namespace {

using namespace e2d;
using physics::Collider;
using physics::Rigidbody;
using physics::test::ComponentScene;

// The message of the error the scene's first frame (or the next one) ends with.
std::string errorOf(ComponentScene& s, std::function<void(core::Scene&)> setup = {}) {
    try {
        if (setup) {
            s.start(std::move(setup));
        }
        s.frames(1);
    } catch (const core::Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(ComponentErrors, ABodyFarOutIsReportedInWorldUnitsNamingItsObject) {
    ComponentScene s(100.0f);
    EXPECT_EQ(errorOf(s,
                      [&](core::Scene& scene) {
                          core::GameObject& crate = scene.createGameObject();
                          crate.setName("crate");
                          crate.setPosition(glm::vec2{1e30f, 0.0f});
                          crate.addComponent<Rigidbody>();
                      }),
              "physics::Rigidbody on object 'crate': world position (1e+30, 0) world units is out "
              "of the physics range (finite, |x| and |y| <= 50000000 world units: 500000 m at 100 "
              "units per metre)");
}

TEST(ComponentErrors, AStaticColliderMovedFarOutByHandNamesItsObjectByTag) {
    ComponentScene s;
    core::GameObject* wall = nullptr;
    s.start([&](core::Scene& scene) {
        wall = &scene.createGameObject();
        wall->setTag("wall");
        wall->addComponent<Collider>(physics::makeBox(1.0f, 1.0f));
    });
    s.frames(1);
    wall->setPosition(glm::vec2{0.0f, -3e6f});
    EXPECT_EQ(
        errorOf(s),
        "physics::Collider on object tagged 'wall': world position (0, -3000000) world units "
        "is out of the physics range (finite, |x| and |y| <= 500000 world units: 500000 m at 1 "
        "units per metre)");
}

// Finite scales whose product overflows (the setters refuse only non-finite values).
TEST(ComponentErrors, AScaleThatOverflowsUnderAColliderNamesTheObjectAndItsScale) {
    ComponentScene s;
    EXPECT_EQ(errorOf(s,
                      [&](core::Scene& scene) {
                          core::GameObject& giant = scene.createGameObject();
                          giant.setScale(1e20f);
                          core::GameObject& coin = scene.createGameObject();
                          coin.setName("coin");
                          giant.addChild(coin);
                          coin.setScale(glm::vec2{1e20f, 1.0f});
                          coin.addComponent<Collider>(physics::makeBox(1.0f, 1.0f));
                      }),
              "physics::Collider on object 'coin': the object's scale, orientation or position "
              "relative to its "
              "body is not finite (scale (1e+20, 1), orientation 0)");
}

} // namespace
