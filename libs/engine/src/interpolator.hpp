// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object_id.hpp>
#include <e2d/render/render_system.hpp>

#include <glm/vec2.hpp>

#include <vector>

namespace e2d::core {
class GameObject;
class Scene;
} // namespace e2d::core

namespace e2d::engine::detail {

/// Draws every object with a Rigidbody between its last two physics states.
///
/// After each fixed step `record()` notes the world position and orientation of every object
/// that has a Rigidbody (the state before is kept). Right before drawing (a RenderHook, after
/// the sprites took their objects' transforms) every sprite of such an object and of its
/// descendants is moved by `lerp(previous, current, alpha) - current`, and the object's own
/// sprites are turned likewise. Objects and transforms are not touched: only what is drawn.
/// An object recorded once only (it just appeared) is drawn where it is.
class Interpolator final : public render::RenderHook {
public:
    void record(const core::Scene& scene);
    void setFrame(const core::Scene* scene, double alpha) noexcept {
        scene_ = scene;
        alpha_ = alpha;
    }
    void clear() noexcept { states_.clear(); }
    void beforeRender(render::Renderer& renderer) override;

    /// Objects with two recorded states (for tests).
    [[nodiscard]] std::size_t tracked() const noexcept { return states_.size(); }

private:
    struct State {
        core::GameObjectId id;
        glm::vec2 previous{0.0f};
        glm::vec2 current{0.0f};
        float previousAngle = 0.0f;
        float currentAngle = 0.0f;
        bool hasPrevious = false;
    };
    void shift(render::Renderer& renderer, const core::GameObject& object, glm::vec2 delta, float turn,
               bool own) const;

    std::vector<State> states_;
    std::vector<State> next_;
    const core::Scene* scene_ = nullptr;
    double alpha_ = 1.0;
};

} // namespace e2d::engine::detail
