// SPDX-License-Identifier: MIT
// apps/hello: the smallest e2d game. A spinning orange square and a label, drawn by the engine
// from one scene; run it with `e2d_hello`, or headless with
// `e2d_hello --frames 60 --screenshot hello.png`.
#include <e2d/engine/game.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

using namespace e2d;

/// A component: turns its object by one radian per second.
class Spin : public core::Component {
public:
    void update(double dt) override { gameObject()->rotate(static_cast<float>(dt)); }
};

/// The scene's objects, made when the scene starts. World units are pixels, y up, the origin at
/// the window's centre.
void makeHello(core::Scene& scene) {
    core::GameObject& square = scene.createGameObject();
    square.setPosition(glm::vec2{0.0f, 40.0f});
    square.addComponent<render::SpriteRenderer>(
        render::SpriteRendererDef{.size = {120.0f, 120.0f}, .tint = {255, 140, 0, 255}});
    square.addComponent<Spin>();

    core::GameObject& label = scene.createGameObject();
    label.setPosition(glm::vec3{0.0f, -120.0f, 1.0f}); // z 1: in front of the square
    label.addComponent<render::TextLabel>(
        render::TextLabelDef{.text = "Hello, e2d!",
                             .pixelSize = 48,
                             .style = {.horizontal = render::HorizontalAlign::Center,
                                       .vertical = render::VerticalAlign::Center}});
}

int main(int argc, char** argv) {
    engine::Game game;
    game.scenes().add("HelloScene", core::SceneFunctions{.initialize = makeHello});
    return game.run(argc, argv, "config.txt"); // config.txt names HelloScene as the first scene
}
