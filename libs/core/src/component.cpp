// SPDX-License-Identifier: MIT
#include <e2d/core/component.hpp>

#include <e2d/core/game_object.hpp>

namespace e2d::core {

Scene* Component::scene() const noexcept {
    return gameObject_ != nullptr ? &gameObject_->scene() : nullptr;
}

} // namespace e2d::core
