// SPDX-License-Identifier: MIT
// Seed demo "physics 2": bodies of three materials side by side. Bouncy balls keep bouncing
// (restitution 0.9), icy blocks slide down their slope (no friction), rough blocks stay put on
// the same slope (friction 1).
//   1 / 2 / 3      choose the material of new bodies
//   left click     drop a body of that material
//   G              physics debug draw on / off (AABBs, contact points and normals)
// World units are metres (the camera shows 25.6 x 18 m).
#include "../common/hud_label.hpp"
#include "../common/shape_view.hpp"

#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/event.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <cmath>
#include <cstdio>

using namespace e2d;

namespace {

constexpr float kViewWidth = 25.6f;
constexpr float kViewHeight = 18.0f;
constexpr float kSlope = -0.35f; // radians: the slopes fall to the right

struct Material {
    const char* name;
    float friction;
    float restitution;
    glm::vec4 colour;
    bool ball; // new bodies are balls, else blocks
};
constexpr Material kMaterials[] = {
    {"bouncy", 0.3f, 0.9f, {1.0f, 0.4f, 0.7f, 1.0f}, true},
    {"icy", 0.0f, 0.0f, {0.6f, 0.9f, 1.0f, 1.0f}, false},
    {"rough", 1.0f, 0.0f, {0.75f, 0.45f, 0.2f, 1.0f}, false},
};

class PhysicsMaterialsScene : public core::Scene, public core::Handles<input::MouseMoved> {
protected:
    void onInitialize() override {
        auto& camera = createGameObject();
        camera.setPosition(glm::vec2{0.0f, kViewHeight / 2 - 1.0f});
        camera.addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kViewWidth, kViewHeight}});

        // Three bays: floor, side walls, dividers.
        const glm::vec4 grey{0.35f, 0.35f, 0.4f, 1.0f};
        addStatic({0.0f, -0.5f}, 0.0f, 13.0f, 0.5f, kMaterials[0], grey);
        addStatic({-12.6f, 8.0f}, 0.0f, 0.3f, 8.0f, kMaterials[2], grey);
        addStatic({12.6f, 8.0f}, 0.0f, 0.3f, 8.0f, kMaterials[2], grey);
        addStatic({-4.27f, 3.0f}, 0.0f, 0.15f, 3.0f, kMaterials[2], grey);
        addStatic({4.27f, 3.0f}, 0.0f, 0.15f, 3.0f, kMaterials[2], grey);
        // The slopes of the icy and rough bays, each made of its own material.
        addStatic({0.0f, 2.5f}, kSlope, 3.6f, 0.2f, kMaterials[1], kMaterials[1].colour * 0.7f);
        addStatic({8.53f, 2.5f}, kSlope, 3.6f, 0.2f, kMaterials[2], kMaterials[2].colour * 0.7f);

        for (int i = 0; i < 3; ++i) {
            addBody({-10.5f + 2.2f * static_cast<float>(i), 5.0f + 3.0f * static_cast<float>(i)},
                    kMaterials[0]);
        }
        // Blocks resting on each slope: along it from its centre, lifted by the slope's and
        // the block's half thickness along its normal.
        const glm::vec2 along{std::cos(kSlope), std::sin(kSlope)};
        const glm::vec2 normal{-along.y, along.x};
        for (int i = 0; i < 3; ++i) {
            const glm::vec2 offset =
                (-2.2f + 1.6f * static_cast<float>(i)) * along + 0.72f * normal;
            addBody(glm::vec2{0.0f, 2.5f} + offset, kMaterials[1], kSlope);
            addBody(glm::vec2{8.53f, 2.5f} + offset, kMaterials[2], kSlope);
        }

        for (int i = 0; i < 3; ++i) {
            auto& title = createGameObject();
            title.setPosition(glm::vec3{-8.53f + 8.53f * static_cast<float>(i), 15.5f, 5.0f});
            title.setScale(1.0f / 40.0f); // font pixels to metres: 40 px per metre on screen
            const glm::vec4 colour = kMaterials[i].colour * 255.0f;
            title.addComponent<render::TextLabel>(render::TextLabelDef{
                .text = kMaterials[i].name,
                .pixelSize = 36,
                .style = {.horizontal = render::HorizontalAlign::Center,
                          .vertical = render::VerticalAlign::Center},
                .color = {static_cast<std::uint8_t>(colour.r), static_cast<std::uint8_t>(colour.g),
                          static_cast<std::uint8_t>(colour.b), 255}});
        }

        info_ = apps::addHudLabel(*this, {kViewWidth, kViewHeight});
    }

    void on(const input::MouseMoved& mouse) override { mouse_ = mouse.world; }

    void update(double dt) override {
        static_cast<void>(dt);
        auto& game = system<engine::GameSystem>();
        const input::ActionMap& actions = game.actions();
        if (actions.pressed("bouncy"))
            selected_ = 0;
        if (actions.pressed("icy"))
            selected_ = 1;
        if (actions.pressed("rough"))
            selected_ = 2;
        if (actions.pressed("debug"))
            game.setDebugDraw(!game.debugDraw());
        // After the material keys, so a key and a click in one frame apply in that order.
        if (actions.pressed("drop"))
            addBody(mouse_, kMaterials[selected_]);

        char text[160];
        std::snprintf(text, sizeof text,
                      "1 / 2 / 3: material (%s)   left click: drop a body   G: debug draw (%s)",
                      kMaterials[selected_].name, game.debugDraw() ? "on" : "off");
        info_->setText(text);
    }

private:
    static physics::ColliderDef colliderOf(const Material& material) {
        return {.friction = material.friction, .restitution = material.restitution};
    }

    void addStatic(glm::vec2 centre, float angle, float hx, float hy, const Material& material,
                   glm::vec4 colour) {
        auto& object = createGameObject();
        object.setPosition(centre);
        object.setOrientation(angle);
        object.addComponent<physics::Collider>(physics::makeBox(hx, hy), colliderOf(material));
        object.addComponent<apps::ShapeView>(colour);
    }

    void addBody(glm::vec2 at, const Material& material, float angle = 0.0f) {
        auto& object = createGameObject();
        object.setPosition(at);
        object.setOrientation(angle);
        object.addComponent<physics::Rigidbody>();
        if (material.ball) {
            object.addComponent<physics::Collider>(physics::Circle{{0.0f, 0.0f}, 0.5f},
                                                   colliderOf(material));
        } else {
            object.addComponent<physics::Collider>(physics::makeBox(0.5f, 0.5f),
                                                   colliderOf(material));
        }
        object.addComponent<apps::ShapeView>(material.colour);
    }

    render::TextLabel* info_ = nullptr;
    int selected_ = 0;
    glm::vec2 mouse_{0.0f, 12.0f};
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), PhysicsMaterialsScene);
    return game.run(argc, argv, "config.txt");
}
