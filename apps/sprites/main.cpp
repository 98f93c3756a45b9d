// SPDX-License-Identifier: MIT
// Seed demo "graphics 1": 12 000 animated sprites from one sprite sheet and an FPS counter.
// Coins spin on the left half of the screen, slimes hop on the right half; every sprite is an
// AnimatedSpriteRenderer playing frames of assets/creatures.json, and all of them are drawn
// in one instanced draw call (one texture).
#include <e2d/core/game_object.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/render/animated_sprite_renderer.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>
#include <e2d/render/text_label.hpp>

#include <chrono>
#include <cstdio>
#include <string>

using namespace e2d;

namespace {

constexpr int kSprites = 12000;
constexpr float kWidth = 1024.0f;
constexpr float kHeight = 720.0f;

// Shows frames per second (wall-clock time, so a headless run with its fixed 1/60 s frames
// still shows how fast it really draws) and what the renderer drew, over half a second.
class FpsCounter : public core::Component {
public:
    void onInitialize() override {
        label_ = gameObject()->getComponent<render::TextLabel>();
        start_ = std::chrono::steady_clock::now();
    }
    void update(double dt) override {
        static_cast<void>(dt);
        ++frames_;
        const auto now = std::chrono::steady_clock::now();
        const double elapsed = std::chrono::duration<double>(now - start_).count();
        if (elapsed >= 0.5) {
            const auto& stats = scene()->system<engine::GameSystem>().renderer().stats();
            char text[96];
            std::snprintf(text, sizeof text, "%.1f FPS   %d sprites   %d draw calls",
                          frames_ / elapsed, stats.sprites, stats.drawCalls);
            label_->setText(text);
            start_ = now;
            frames_ = 0;
        }
    }

private:
    render::TextLabel* label_ = nullptr;
    std::chrono::steady_clock::time_point start_;
    int frames_ = 0;
};

class SpritesScene : public core::Scene {
protected:
    void onInitialize() override {
        auto& game = system<engine::GameSystem>();

        // World units are pixels: (0, 0) at the bottom-left corner of a 1024 x 720 view.
        auto& camera = createGameObject();
        camera.setPosition(glm::vec2{kWidth / 2, kHeight / 2});
        camera.addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kWidth, kHeight}});

        // One parse of the sheet for every sprite; its frames' UV rectangles per animation.
        // Without the sheet (the error is logged) the image path draws the checker placeholder.
        const render::SpriteSheet* sheet =
            game.renderSystem().sheet(game.asset("assets/creatures.json"));
        auto creature = [&](const char* animation) {
            if (sheet == nullptr) {
                return render::AnimatedSpriteRendererDef{
                    .sprite = {.texturePath = game.asset("assets/creatures.png").string(),
                               .size = {32.0f, 32.0f}},
                    .frames = {render::AnimationFrame{render::kFullUv}},
                    .animation = {.frameDuration = 0.08}};
            }
            return render::AnimatedSpriteRendererDef{
                .sprite = {.texturePath = sheet->imagePath().string()},
                .frames = render::animationUvs(*sheet, animation),
                .animation = {.frameDuration = 0.08}};
        };
        render::AnimatedSpriteRendererDef coin = creature("coin");
        render::AnimatedSpriteRendererDef slime = creature("slime");

        core::Random& random = game.random();
        for (int i = 0; i < kSprites; ++i) {
            const bool isCoin = i % 2 == 0;
            render::AnimatedSpriteRendererDef& def = isCoin ? coin : slime;
            auto& sprite = createGameObject();
            // Centres 16 px (half a sprite) inside each half, so a 32 px lane stays clear.
            const float x = isCoin ? random.range(16.0f, kWidth / 2 - 32)
                                   : random.range(kWidth / 2 + 32, kWidth - 16);
            sprite.setPosition(glm::vec3{x, random.range(16.0f, kHeight - 56), 0.0f});
            def.animation.startFrame = random.range(0, static_cast<int>(def.frames.size()) - 1);
            sprite.addComponent<render::AnimatedSpriteRenderer>(def);
        }

        // The counter: HUD text at the top-right (camera units, origin at the view's centre).
        // The top-left corner holds the engine's frame profile overlay (config showProfile,
        // toggled with F2): where each frame's milliseconds go.
        auto& fps = createGameObject();
        fps.setPosition(glm::vec3{kWidth / 2 - 12, kHeight / 2 - 10, 10.0f});
        fps.addComponent<render::TextLabel>(
            render::TextLabelDef{.text = "measuring...",
                                 .pixelSize = 24,
                                 .style = {.horizontal = render::HorizontalAlign::Right},
                                 .hud = true});
        fps.addComponent<FpsCounter>();
    }
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), SpritesScene);
    return game.run(argc, argv, "config.txt");
}
