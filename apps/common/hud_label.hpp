// SPDX-License-Identifier: MIT
// The physics demos' text in the top left corner of a view laid out in metres (40 px each).
#pragma once

#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/render/text_label.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace e2d::apps {

/// A HUD label in `scene` at the top left of a camera view of `viewSize` metres. HUD positions
/// are camera units (metres here) from the view's centre; the scale makes one font pixel one
/// screen pixel at 40 px per metre.
inline render::TextLabel* addHudLabel(core::Scene& scene, glm::vec2 viewSize) {
    auto& info = scene.createGameObject();
    info.setPosition(glm::vec3{-viewSize.x / 2 + 0.7f, viewSize.y / 2 - 0.2f, 10.0f});
    info.setScale(1.0f / 40.0f);
    return info.addComponent<render::TextLabel>(render::TextLabelDef{.pixelSize = 18, .hud = true});
}

} // namespace e2d::apps
