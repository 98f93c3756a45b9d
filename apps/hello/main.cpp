// SPDX-License-Identifier: MIT
// apps/hello: the smallest e2d game. A spinning orange square and a label, drawn by the engine
// from one scene; run it with `e2d_hello`, or headless with
// `e2d_hello --frames 60 --screenshot hello.png`.
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text.hpp>
#include <e2d/render/text_renderer.hpp>

#include <string>

namespace {

using namespace e2d;

/// Draws a line of text at its object, every frame, through the RenderSystem's TextRenderer.
class Label : public core::Component, public render::RenderHook {
public:
    Label(std::string text, int pixelSize, render::Color color) : text_(std::move(text)), size_(pixelSize), color_(color) {}

    void onInitialize() override { scene()->system<render::RenderSystem>().addHook(*this); }
    void onTerminate() override { scene()->system<render::RenderSystem>().removeHook(*this); }

    void beforeRender(render::Renderer&) override {
        render::RenderSystem& renderSystem = scene()->system<render::RenderSystem>();
        render::Font* font = renderSystem.text().font(render::kDefaultFontPath, size_);
        if (font == nullptr) {
            return;
        }
        render::TextStyle style;
        style.horizontal = render::HorizontalAlign::Center;
        style.vertical = render::VerticalAlign::Center;
        render::TextDraw where;
        const glm::vec3 p = gameObject()->worldPosition();
        where.position = {p.x, p.y};
        where.z = p.z;
        where.color = color_;
        renderSystem.text().draw(*font, text_, style, where);
    }

private:
    std::string text_;
    int size_;
    render::Color color_;
};

/// Turns its object at a fixed rate.
class Spin : public core::Component {
public:
    void update(double dt) override { gameObject()->rotate(static_cast<float>(dt)); }
};

class HelloScene : public core::Scene {
protected:
    void onInitialize() override {
        const engine::GameSystem& game = system<engine::GameSystem>();

        core::GameObject& square = createGameObject();
        square.setPosition(glm::vec2{0.0f, 40.0f});
        render::SpriteRendererDef sprite;
        sprite.size = {120.0f, 120.0f};
        sprite.tint = {255, 140, 0, 255};
        square.addComponent<render::SpriteRenderer>(sprite);
        square.addComponent<Spin>();

        core::GameObject& label = createGameObject();
        label.setPosition(glm::vec3{0.0f, -120.0f, 1.0f});
        label.addComponent<Label>("Hello, e2d!", game.config().fontSize, render::Color{255, 255, 255, 255});
    }
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), HelloScene);
    return game.run(argc, argv, "config.txt");
}
