// SPDX-License-Identifier: MIT
// Seed demo "graphics 3": a text whose horizontal and vertical alignment are switched with the
// keyboard (H / V, or the arrow keys), through the input actions "horizontal" and "vertical"
// (so an --input-script can press them too). The cross marks the label's anchor: the
// object's position, which the alignment places the text around.
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <array>
#include <string>

using namespace e2d;

namespace {

constexpr float kWidth = 1024.0f;
constexpr float kHeight = 720.0f;

constexpr std::array kHorizontal = {render::HorizontalAlign::Left, render::HorizontalAlign::Center,
                                    render::HorizontalAlign::Right};
constexpr std::array kVertical = {render::VerticalAlign::Top, render::VerticalAlign::Center,
                                  render::VerticalAlign::Bottom};
constexpr std::array kHorizontalNames = {"left", "center", "right"};
constexpr std::array kVerticalNames = {"top", "center", "bottom"};

class TextScene : public core::Scene {
protected:
    void onInitialize() override {
        auto& camera = createGameObject();
        camera.addComponent<render::CameraComponent>( // world (0, 0) at the centre
            render::CameraComponentDef{.referenceSize = {kWidth, kHeight}});

        auto& text = createGameObject();
        label_ = text.addComponent<render::TextLabel>(render::TextLabelDef{
            .text = "e2d draws text\nwith FreeType, kerned,\naligned as you like",
            .pixelSize = 44,
            .color = {255, 230, 140, 255}});

        auto& help = createGameObject();
        help.setPosition(glm::vec3{-kWidth / 2 + 12, -kHeight / 2 + 12, 10.0f});
        help_ = help.addComponent<render::TextLabel>(
            render::TextLabelDef{.pixelSize = 20,
                                 .style = {.vertical = render::VerticalAlign::Bottom},
                                 .color = {180, 200, 255, 255},
                                 .hud = true});
        apply();
    }

    void update(double dt) override {
        static_cast<void>(dt);
        auto& game = system<engine::GameSystem>();
        const input::ActionMap& actions = game.actions();
        const int h = horizontal_;
        const int v = vertical_;
        if (actions.pressed("horizontal"))
            horizontal_ = (horizontal_ + 1) % 3;
        if (actions.pressed("horizontal_back"))
            horizontal_ = (horizontal_ + 2) % 3;
        if (actions.pressed("vertical"))
            vertical_ = (vertical_ + 1) % 3;
        if (actions.pressed("vertical_back"))
            vertical_ = (vertical_ + 2) % 3;
        if (h != horizontal_ || v != vertical_) {
            apply();
        }

        // The anchor: a cross at the label's position, in world units.
        render::Drawer& draw = game.renderer().drawer();
        const glm::vec4 red{1.0f, 0.2f, 0.2f, 1.0f};
        draw.line({-20.0f, 0.0f}, {20.0f, 0.0f}, red, 2.0f);
        draw.line({0.0f, -20.0f}, {0.0f, 20.0f}, red, 2.0f);
    }

private:
    void apply() {
        label_->setAlignment(kHorizontal[horizontal_], kVertical[vertical_]);
        help_->setText(std::string("H / left / right: horizontal (") +
                       kHorizontalNames[horizontal_] + ")     V / up / down: vertical (" +
                       kVerticalNames[vertical_] + ")");
    }

    render::TextLabel* label_ = nullptr;
    render::TextLabel* help_ = nullptr;
    int horizontal_ = 1; // center
    int vertical_ = 1;   // center
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), TextScene);
    return game.run(argc, argv, "config.txt");
}
