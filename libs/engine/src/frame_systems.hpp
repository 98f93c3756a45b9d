// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>

namespace e2d::engine::detail {

struct GameState;

/// The engine's part of a frame before the libraries' systems (registered first): the window's
/// events are read (a close request ends the game after this frame) and the scene learns the
/// window size; before drawing, the physics debug draw is queued (objects are drawn where
/// core::GameObject::renderTransform() says, from the alpha the loop gives the scene).
class FrameStart final : public core::System {
public:
    explicit FrameStart(GameState& state) noexcept : state_(state) {}
    void beginFrame() override;
    void render(double alpha) override;

private:
    GameState& state_;
};

/// The engine's part of a frame after every other system (registered last): the debug and
/// profile keys, and after drawing the screenshot of a `--frames N --screenshot` run's last
/// frame and the buffer swap.
class FrameEnd final : public core::System {
public:
    explicit FrameEnd(GameState& state) noexcept : state_(state) {}
    void beginFrame() override;
    void render(double alpha) override;

private:
    GameState& state_;
};

} // namespace e2d::engine::detail
