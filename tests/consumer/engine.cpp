// SPDX-License-Identifier: MIT
// Uses the installed engine: a Game with one scene (a sprite, a rigid body falling on a static
// collider) run headless for a few frames from a config file it writes, exit code checked.
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/rigidbody.hpp>
#include <e2d/render/sprite_renderer.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace {

class FallScene : public e2d::core::Scene {
public:
    explicit FallScene(bool& failed) : failed_(failed) {}

protected:
    void onInitialize() override {
        using namespace e2d;
        core::GameObject& ground = createGameObject();
        ground.setPosition(glm::vec2{0.0f, -2.0f});
        ground.addComponent<physics::Collider>(
            physics::ShapeGeometry{physics::makeBox(10.0f, 1.0f)});
        core::GameObject& box = createGameObject();
        box.setName("box");
        render::SpriteRendererDef sprite;
        sprite.size = {1.0f, 1.0f};
        box.addComponent<render::SpriteRenderer>(sprite);
        box.addComponent<physics::Rigidbody>(physics::RigidbodyDef{});
        box.addComponent<physics::Collider>(physics::ShapeGeometry{physics::makeBox(0.5f, 0.5f)});
    }
    void update(double) override {
        if (system<e2d::engine::GameSystem>().frame() == 59) {
            const float y = findByName("box")->worldPosition().y;
            std::printf("consumer: after 60 frames the box is at y = %.3f (resting on the ground "
                        "at -0.5)\n",
                        y);
            if (y < -0.6f || y > -0.4f) {
                terminateGame();
                failed_ = true;
            }
        }
    }

private:
    bool& failed_;
};

} // namespace

int main() {
    const std::filesystem::path config =
        std::filesystem::temp_directory_path() / "e2d_consumer_engine.txt";
    std::ofstream(config)
        << "firstScene = FallScene\nwindowWidth = 64\nwindowHeight = 64\n"
           "referenceWindowWidth = 16\nreferenceWindowHeight = 16\nunitsPerMetre = 1\n";
    e2d::engine::Game game;
    bool failed = false;
    game.scenes().add("FallScene", [&failed] { return std::make_unique<FallScene>(failed); });
    std::string args[] = {"e2d_consumer", "--config", config.string(), "--frames", "60"};
    char* argv[] = {args[0].data(), args[1].data(), args[2].data(),
                    args[3].data(), args[4].data(), nullptr};
    const int code = game.run(5, argv);
    std::filesystem::remove(config);
    if (code != 0 || failed) {
        std::fprintf(stderr, "consumer: the engine game failed (exit code %d)\n", code);
        return 1;
    }
    std::printf("consumer: e2d::engine ran %lld frames\n",
                static_cast<long long>(game.profile().frames));
    return 0;
}
