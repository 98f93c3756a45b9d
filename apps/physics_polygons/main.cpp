// SPDX-License-Identifier: MIT
// Seed demo "physics 1": create polygons of 3 to 8 sides with the mouse, choose their mass,
// push them with ray-cast impulses and fire projectiles at them from the cannon on the left.
//   left click         create a polygon (sides: up / down, mass: M)
//   right click or P   cast a ray from the cannon towards the mouse: the first body it hits
//                      gets an impulse where the ray hits it
//   space              fire a projectile from the cannon towards the mouse
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
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>
#include <e2d/physics/world.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <glm/geometric.hpp>

#include <cstdio>

using namespace e2d;

namespace {

constexpr float kViewWidth = 25.6f;
constexpr float kViewHeight = 18.0f;
constexpr glm::vec2 kCannon{-11.5f, 1.5f};
constexpr float kProjectileSpeed = 22.0f; // m/s
constexpr float kRayImpulse = 12.0f;      // N*s

struct Mass {
    const char* name;
    float density; // kg/m^2
    glm::vec4 colour;
};
constexpr Mass kMasses[] = {
    {"light", 0.5f, {0.55f, 0.85f, 1.0f, 1.0f}},
    {"medium", 2.0f, {0.3f, 0.55f, 0.95f, 1.0f}},
    {"heavy", 10.0f, {0.15f, 0.25f, 0.7f, 1.0f}},
};

class PhysicsPolygonsScene : public core::Scene, public core::Handles<input::MouseMoved> {
protected:
    void onInitialize() override {
        auto& camera = createGameObject();
        camera.setPosition(glm::vec2{0.0f, kViewHeight / 2 - 1.0f});
        camera.addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kViewWidth, kViewHeight}});

        // Ground and walls: colliders without a Rigidbody are static.
        addStatic({0.0f, -0.5f}, 13.0f, 0.5f);
        addStatic({-12.6f, 8.0f}, 0.3f, 8.0f);
        addStatic({12.6f, 8.0f}, 0.3f, 8.0f);

        // Something to play with: a small pyramid of boxes and a row of polygons of every
        // side count and mass.
        for (int row = 0; row < 4; ++row) {
            for (int i = 0; i < 4 - row; ++i) {
                addPolygon({3.0f + static_cast<float>(i) * 1.05f + static_cast<float>(row) * 0.525f,
                            0.5f + static_cast<float>(row) * 1.0f},
                           4, 0.7f, kMasses[row % 3], 0.785398f);
            }
        }
        for (int sides = 3; sides <= 8; ++sides) {
            addPolygon({-8.0f + static_cast<float>(sides - 3) * 1.6f, 2.0f}, sides, 0.6f,
                       kMasses[sides % 3], 0.0f);
        }

        info_ = apps::addHudLabel(*this, {kViewWidth, kViewHeight});
    }

    // The mouse's world position: where new polygons go and where the cannon aims.
    void on(const input::MouseMoved& mouse) override { aim_ = mouse.world; }

    void update(double dt) override {
        auto& game = system<engine::GameSystem>();
        const input::ActionMap& actions = game.actions();
        if (actions.pressed("more_sides") && sides_ < 8)
            ++sides_;
        if (actions.pressed("fewer_sides") && sides_ > 3)
            --sides_;
        if (actions.pressed("mass"))
            mass_ = (mass_ + 1) % 3;
        // After the choices above, so a key and a click in one frame apply in that order.
        if (actions.pressed("create"))
            addPolygon(aim_, sides_, 0.6f, kMasses[mass_], 0.0f);
        if (actions.pressed("fire"))
            fire();
        if (actions.pressed("push"))
            push();

        render::Drawer& draw = game.renderer().drawer();
        // The cannon, aimed at the mouse.
        const glm::vec2 direction = aimDirection();
        draw.fillCircle(kCannon, 0.45f, {0.8f, 0.8f, 0.8f, 1.0f});
        draw.line(kCannon, kCannon + direction * 1.1f, {0.8f, 0.8f, 0.8f, 1.0f}, 8.0f);
        if (rayTime_ > 0.0) {
            rayTime_ -= dt;
            draw.line(kCannon, rayEnd_, {1.0f, 0.9f, 0.2f, 1.0f}, 2.0f);
            draw.fillCircle(rayEnd_, 0.12f, {1.0f, 0.9f, 0.2f, 1.0f});
        }

        char text[200];
        std::snprintf(text, sizeof text,
                      "left click: create a %d-sided %s polygon (up/down: sides, M: mass)\n"
                      "space: fire   right click / P: ray-cast impulse   bodies: %d",
                      sides_, kMasses[mass_].name, bodies_);
        info_->setText(text);
    }

private:
    glm::vec2 aimDirection() const {
        const glm::vec2 d = aim_ - kCannon;
        const float length = glm::length(d);
        return length > 1e-3f ? d / length : glm::vec2{1.0f, 0.0f};
    }

    void addStatic(glm::vec2 centre, float hx, float hy) {
        auto& object = createGameObject();
        object.setPosition(centre);
        object.addComponent<physics::Collider>(physics::makeBox(hx, hy));
        object.addComponent<apps::ShapeView>(glm::vec4{0.35f, 0.35f, 0.4f, 1.0f});
    }

    core::GameObject& addPolygon(glm::vec2 at, int sides, float radius, const Mass& mass,
                                 float angle) {
        auto& object = createGameObject();
        object.setPosition(at);
        object.setOrientation(angle);
        object.addComponent<physics::Rigidbody>();
        object.addComponent<physics::Collider>(
            apps::regularPolygon(sides, radius),
            physics::ColliderDef{.density = mass.density, .friction = 0.5f});
        object.addComponent<apps::ShapeView>(mass.colour);
        ++bodies_;
        return object;
    }

    void fire() {
        auto& object = createGameObject();
        object.setPosition(kCannon + aimDirection() * 1.2f);
        object.addComponent<physics::Rigidbody>(physics::RigidbodyDef{
            .linearVelocity = aimDirection() * kProjectileSpeed, .isBullet = true});
        object.addComponent<physics::Collider>(
            physics::Circle{{0.0f, 0.0f}, 0.2f},
            physics::ColliderDef{.density = 8.0f, .restitution = 0.3f});
        object.addComponent<apps::ShapeView>(glm::vec4{1.0f, 0.4f, 0.2f, 1.0f});
        ++bodies_;
    }

    // The seed's ray-cast impulse: the closest shape on the ray from the cannon is pushed
    // along the ray, at the point hit (so it also spins).
    void push() {
        // The physics system's queries speak world units, like its components.
        auto& simulation = system<physics::PhysicsSystem>();
        const glm::vec2 direction = aimDirection();
        const glm::vec2 translation = direction * 40.0f;
        rayEnd_ = kCannon + translation;
        rayTime_ = 0.3;
        const auto hit = simulation.castRayClosest(kCannon, translation);
        if (!hit) {
            return;
        }
        rayEnd_ = hit->point;
        const physics::Collider* collider = simulation.collider(hit->shape);
        if (collider == nullptr) {
            return;
        }
        if (auto* body = collider->gameObject()->getComponent<physics::Rigidbody>()) {
            body->applyImpulseAtPoint(direction * kRayImpulse, hit->point);
        }
    }

    render::TextLabel* info_ = nullptr;
    int sides_ = 5;
    int mass_ = 1;
    int bodies_ = 0;
    glm::vec2 aim_{6.0f, 2.0f};
    glm::vec2 rayEnd_{0.0f, 0.0f};
    double rayTime_ = 0.0;
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), PhysicsPolygonsScene);
    return game.run(argc, argv, "config.txt");
}
