// SPDX-License-Identifier: MIT
// Seed demo "graphics 2": translucent circles in four layers with parallax while the camera
// moves. Far layers follow the camera less (SpriteRendererDef::parallax), so they seem to
// drift slowly behind the near ones; every circle is half transparent, so the layers show
// through each other. The camera glides on its own; the arrow keys push it too.
#include <e2d/core/game_object.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <cmath>
#include <cstdio>

using namespace e2d;

namespace {

constexpr float kWidth = 1024.0f;
constexpr float kHeight = 720.0f;
constexpr float kCameraSpeed = 120.0f; // world units per second, along x
constexpr float kMarkerY = -310.0f;    // world y of the layer markers (the view spans -360..360)

struct Layer {
    float parallax; // how much of the camera's movement the layer follows
    float z;        // draw order: larger is nearer
    float minSize;  // circle diameters, world units
    float maxSize;
    render::Color tint; // colour and transparency
    int count;
};

// Far to near: small, dim and slow at the back; large, bright and fast at the front.
constexpr Layer kLayers[] = {
    {0.2f, 1.0f, 30.0f, 60.0f, {70, 90, 200, 110}, 60},
    {0.45f, 2.0f, 60.0f, 110.0f, {60, 170, 200, 120}, 40},
    {0.7f, 3.0f, 100.0f, 170.0f, {120, 210, 90, 120}, 26},
    {1.0f, 4.0f, 150.0f, 260.0f, {240, 120, 60, 130}, 16},
};

// Moves its object (the camera) along x at a steady speed, plus the actions camera_x and
// camera_y (the arrow keys, in [-1, 1]).
class CameraMover : public core::Component {
public:
    void update(double dt) override {
        const input::ActionMap& actions = scene()->system<engine::GameSystem>().actions();
        const glm::vec2 push{actions.value("camera_x"), actions.value("camera_y")};
        const float speed = kCameraSpeed;
        gameObject()->translate((glm::vec2{1.0f, 0.0f} + 3.0f * push) * speed *
                                static_cast<float>(dt));
    }
};

class ParallaxScene : public core::Scene {
protected:
    void onInitialize() override {
        auto& game = system<engine::GameSystem>();

        auto& camera = createGameObject();
        camera.setPosition(glm::vec2{0.0f, 0.0f});
        camera.addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kWidth, kHeight}});
        camera.addComponent<CameraMover>();

        core::Random& random = game.random();
        const std::string circle = game.asset("assets/circle.png").string();
        // A circle of `size` world units drawn in its layer's colour, at its layer's parallax.
        auto circleOf = [&circle](const Layer& layer, float size) {
            return render::SpriteRendererDef{.texturePath = circle,
                                             .size = {size, size},
                                             .tint = layer.tint,
                                             .parallax = layer.parallax};
        };
        for (const Layer& layer : kLayers) {
            // Spread each layer over a strip much wider than the view, so the glide lasts.
            for (int i = 0; i < layer.count; ++i) {
                // The bottom band (below y -280) is kept for the markers.
                const float size = random.range(layer.minSize, layer.maxSize);
                auto& object = createGameObject();
                object.setPosition(glm::vec3{random.range(-kWidth, 4 * kWidth),
                                             random.range(-280.0f + size / 2, kHeight / 2),
                                             layer.z});
                object.addComponent<render::SpriteRenderer>(circleOf(layer, size));
            }
        }

        // One marker per layer along the bottom, all at x = 0: lined up when the camera starts,
        // they drift apart as it moves, each by its layer's share of the camera's movement.
        // Parallax scales the offset from the camera on both axes, so a layer's marker sits at
        // kMarkerY / parallax to be drawn at kMarkerY while the camera is at y 0.
        for (const Layer& layer : kLayers) {
            auto& marker = createGameObject();
            marker.setPosition(glm::vec3{0.0f, kMarkerY / layer.parallax, layer.z});
            marker.addComponent<render::SpriteRenderer>(circleOf(layer, 36.0f));
        }

        auto& help = createGameObject();
        help.setPosition(glm::vec3{-kWidth / 2 + 12, kHeight / 2 - 10, 10.0f});
        help.addComponent<render::TextLabel>(render::TextLabelDef{
            .text = "Parallax: four layers of translucent circles. Arrow keys move the camera.\n"
                    "The four circles at the bottom were lined up when the camera started.",
            .pixelSize = 20,
            .hud = true});
    }
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), ParallaxScene);
    return game.run(argc, argv, "config.txt");
}
