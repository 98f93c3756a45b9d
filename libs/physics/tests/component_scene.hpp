// SPDX-License-Identifier: MIT
// A real scene run by a core::SceneDirector with a PhysicsSystem plugged in, stepped by hand at
// 60 Hz: what the component tests build their scenes in.
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/physics_system.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace e2d::physics::test {

inline constexpr double kStep = 1.0 / 60.0;

/// Owns the system (at `unitsPerMetre`) and the director; start() runs `setup` as the scene's
/// initialization, frames() runs frames of one fixed step each.
class ComponentScene {
public:
    explicit ComponentScene(float unitsPerMetre = 1.0f, const WorldDef& def = {})
        : physics(def, unitsPerMetre) {}

    void start(std::function<void(core::Scene&)> setup) {
        registry.add("Test", core::SceneFunctions{.initialize = std::move(setup)});
        director.addSystem(physics);
        ASSERT_TRUE(director.start("Test"));
    }
    void frames(int n) {
        for (int i = 0; i < n; ++i) {
            director.applyPendingChange();
            director.scene()->beginFrame();
            physics.fixedUpdate(kStep);
        }
    }
    [[nodiscard]] core::Scene& scene() { return *director.scene(); }

    core::Logger logger{core::LogLevel::Off};
    core::SceneRegistry registry;
    core::SceneDirector director{registry, logger};
    PhysicsSystem physics;
};

/// Records the physics events its object receives.
class EventLog : public core::Component,
                 public core::Handles<CollisionEnter, CollisionExit, TriggerEnter, TriggerExit> {
public:
    struct Event {
        std::string kind;
        ContactInfo info;
    };
    void on(const CollisionEnter& c) override { events.push_back({"enter", c}); }
    void on(const CollisionExit& c) override { events.push_back({"exit", c}); }
    void on(const TriggerEnter& c) override { events.push_back({"trigger-enter", c}); }
    void on(const TriggerExit& c) override { events.push_back({"trigger-exit", c}); }
    /// The kinds in the order they arrived ("enter", "trigger-exit", ...).
    [[nodiscard]] std::vector<std::string> kinds() const {
        std::vector<std::string> out;
        for (const Event& e : events) {
            out.push_back(e.kind);
        }
        return out;
    }
    [[nodiscard]] int count(const std::string& kind) const {
        int n = 0;
        for (const Event& e : events) {
            n += e.kind == kind ? 1 : 0;
        }
        return n;
    }
    std::vector<Event> events;
};

} // namespace e2d::physics::test
