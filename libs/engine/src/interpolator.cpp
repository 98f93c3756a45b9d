// SPDX-License-Identifier: MIT
#include "interpolator.hpp"

#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/rigidbody.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace e2d::engine::detail {

void Interpolator::record(const core::Scene& scene) {
    next_.clear();
    for (const core::GameObject* object : scene.gameObjects()) {
        const auto* body = object->getComponent<physics::Rigidbody>();
        if (body == nullptr || body->body().isNull()) {
            continue;
        }
        State state;
        state.id = object->id();
        const glm::vec3 p = object->worldPosition();
        state.current = {p.x, p.y};
        state.currentAngle = object->worldOrientation();
        const auto old = std::find_if(states_.begin(), states_.end(),
                                      [&state](const State& s) { return s.id == state.id; });
        if (old != states_.end()) {
            state.previous = old->current;
            state.previousAngle = old->currentAngle;
            state.hasPrevious = true;
        }
        next_.push_back(state);
    }
    states_.swap(next_);
}

void Interpolator::beforeRender(render::Renderer& renderer) {
    if (scene_ == nullptr) {
        return;
    }
    const float a = static_cast<float>(alpha_);
    for (const State& s : states_) {
        if (!s.hasPrevious) {
            continue;
        }
        const core::GameObject* object = scene_->find(s.id);
        if (object == nullptr) {
            continue;
        }
        // Only while the object is where the last step put it (not moved by hand since).
        const glm::vec3 p = object->worldPosition();
        if (p.x != s.current.x || p.y != s.current.y) {
            continue;
        }
        const glm::vec2 drawn = s.previous + (s.current - s.previous) * a;
        float turn = s.currentAngle - s.previousAngle;
        turn = std::remainder(turn, 2.0f * std::numbers::pi_v<float>);
        shift(renderer, *object, drawn - s.current, -turn * (1.0f - a), true);
    }
}

void Interpolator::shift(render::Renderer& renderer, const core::GameObject& object, glm::vec2 delta, float turn,
                         bool own) const {
    for (const render::SpriteRenderer* sprite : object.getComponents<render::SpriteRenderer>()) {
        const render::SpriteId id = sprite->sprite();
        if (!renderer.isValid(id)) {
            continue;
        }
        const render::SpriteDef& def = renderer.sprite(id);
        if (def.hud) {
            continue;
        }
        renderer.setPosition(id, def.position + delta);
        if (own) {
            renderer.setRotation(id, def.rotation + turn);
        }
    }
    for (const core::GameObject* child : object.children()) {
        shift(renderer, *child, delta, turn, false);
    }
}

} // namespace e2d::engine::detail
