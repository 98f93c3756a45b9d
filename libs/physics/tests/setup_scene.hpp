// SPDX-License-Identifier: MIT
// The physics component tests' scene: it runs a test's setup function when it initialises, so
// each test builds its game objects in a lambda and registers the scene under any name.
#pragma once

#include <e2d/core/scene.hpp>

#include <functional>
#include <utility>

namespace e2d::physics::test {

class SetupScene : public core::Scene {
public:
    explicit SetupScene(std::function<void(core::Scene&)> setup) : setup_(std::move(setup)) {}

protected:
    void onInitialize() override { setup_(*this); }

private:
    std::function<void(core::Scene&)> setup_;
};

} // namespace e2d::physics::test
