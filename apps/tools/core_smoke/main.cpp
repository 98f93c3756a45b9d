// SPDX-License-Identifier: MIT
// A headless run of e2d::core: the seed's configuration file, two registered scenes, a game
// loop fed by a scripted clock with uneven frames, a scene change and a termination. It prints
// what happened and exits non-zero if the loop did not behave as the configuration says.
#include <e2d/core/clock.hpp>
#include <e2d/core/component.hpp>
#include <e2d/core/config.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/game_loop.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/core/system.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

constexpr const char* kConfigText = R"(#SCENE
firstScene = Orbit

#LOOP
fixedTimestep = 0.01
maxStepsPerFrame = 4
randomSeed = 42
)";

// The settings this program reads with core's `key = value` reader.
struct SmokeConfig {
    std::string firstScene;
    double fixedTimestep = 1.0 / 60.0;
    int maxStepsPerFrame = 5;
    std::uint64_t randomSeed = 0;
};

// Turns its object at a fixed rate, in fixed steps.
class Spinner : public e2d::core::Component {
public:
    static constexpr bool kUnique = true;
    explicit Spinner(float rate) : rate_(rate) {}
    void fixedUpdate(double step) override {
        gameObject()->rotate(rate_ * static_cast<float>(step));
    }

private:
    float rate_;
};

// Counts the fixed steps the loop ran, as a physics system would.
class StepCounter : public e2d::core::System {
public:
    void fixedUpdate(double) override { ++steps; }
    void clear() override { ++clears; }
    long steps = 0;
    int clears = 0;
};

class OrbitScene : public e2d::core::Scene {
protected:
    void onInitialize() override {
        e2d::core::GameObject& sun = createGameObject();
        sun.addComponent<Spinner>(1.0f);
        e2d::core::GameObject& planet = createGameObject();
        planet.setPosition({10.0f, 0.0f, 0.0f});
        sun.addChild(planet);
        sunId = sun.id();
        planetId = planet.id();
    }
    void update(double) override {
        elapsed += 1;
        if (elapsed == 120) {
            const e2d::core::GameObject* planet = find(planetId);
            const glm::vec3 p = planet->worldPosition();
            std::printf("orbit: after 120 frames the planet is at (%.3f, %.3f)\n", p.x, p.y);
            changeToScene("Finale");
        }
    }

public:
    e2d::core::GameObjectId sunId{};
    e2d::core::GameObjectId planetId{};
    int elapsed = 0;
};

class FinaleScene : public e2d::core::Scene {
protected:
    void update(double) override {
        if (++frames == 10) {
            terminateGame();
        }
    }
    int frames = 0;
};

} // namespace

int main() {
    using namespace e2d::core;
    Logger logger(LogLevel::Info);

    SmokeConfig config;
    ConfigReader reader;
    reader.add("firstScene", config.firstScene);
    reader.add("fixedTimestep", config.fixedTimestep, ConfigBounds{0.0, 1.0, true});
    reader.add("maxStepsPerFrame", config.maxStepsPerFrame, ConfigBounds::atLeast(1.0));
    reader.add("randomSeed", config.randomSeed);
    const ConfigReport parsed = reader.read(kConfigText, "smoke.cfg");
    for (const auto& d : parsed.diagnostics) {
        logger.warning(d.toString());
    }
    if (!parsed.diagnostics.ok()) {
        return 1;
    }

    SceneRegistry registry;
    E2D_REGISTER_SCENE(registry, OrbitScene);
    registry.add<FinaleScene>("Finale");
    registry.add<OrbitScene>("Orbit");

    // A scripted clock: frames of 16 ms with a 200 ms hitch every 50 frames.
    double now = 0.0;
    int frame = 0;
    Clock clock([&] { return now; });
    FixedStepper stepper(config.fixedTimestep, config.maxStepsPerFrame);
    SceneDirector director(registry, logger);
    StepCounter counter;
    director.addSystem(counter);
    GameLoop loop(director, stepper, clock);
    if (!loop.start(config.firstScene)) {
        return 1;
    }

    Random random(static_cast<std::uint64_t>(config.randomSeed));
    int changes = 0;
    int clamped = 0;
    while (loop.running() && frame < 10000) {
        now += (++frame % 50 == 0) ? 0.2 : 0.016 + 0.001 * random.range(-1, 1);
        const FrameInfo info = loop.frame();
        changes += info.sceneChanged ? 1 : 0;
        clamped += info.fixedSteps == config.maxStepsPerFrame ? 1 : 0;
    }
    loop.shutdown();

    std::printf("frames: %d, fixed steps: %ld, frames at the step clamp: %d, scene changes: %d, "
                "system clears: %d, final scene: %s\n",
                frame, counter.steps, clamped, changes, counter.clears,
                director.scene() ? director.sceneName().c_str() : "(none)");
    // 130 frames ran (120 in Orbit, 10 in Finale); each ran at most maxStepsPerFrame steps.
    const bool ok = frame == 130 && changes == 1 && counter.clears == 1 && clamped >= 2 &&
                    counter.steps <= static_cast<long>(frame) * config.maxStepsPerFrame;
    std::printf("core smoke run: %s\n", ok ? "ok" : "UNEXPECTED");
    return ok ? 0 : 1;
}
