// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/function_scene.hpp>
#include <e2d/core/scene.hpp>

#include <concepts>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::core {

/// Creates scenes by name (owned by the game, not global).
///
/// Every `create()` builds a fresh scene, so entering a scene twice starts it from scratch.
class SceneRegistry {
public:
    using Factory = std::function<std::unique_ptr<Scene>()>;

    /// Registers default-constructible scene type T under `name`.
    template <class T>
    requires std::derived_from<T, Scene> && std::default_initializable<T>
    void add(std::string name) {
        add(std::move(name), [] { return std::unique_ptr<Scene>(std::make_unique<T>()); });
    }

    /// Registers `factory` under `name`. Throws core::Error for an empty name, an empty
    /// factory or a name already registered.
    void add(std::string name, Factory factory);

    /// Registers a FunctionScene made of `functions` under `name` (each create() makes a new
    /// one with copies of them). Throws as the factory overload does.
    void add(std::string name, SceneFunctions functions);

    /// A new scene of the type registered as `name`, or nullptr for an unknown name.
    [[nodiscard]] std::unique_ptr<Scene> create(std::string_view name) const;
    [[nodiscard]] bool contains(std::string_view name) const;
    /// Registered names, sorted.
    [[nodiscard]] std::vector<std::string> names() const;

private:
    std::map<std::string, Factory, std::less<>> factories_;
};

} // namespace e2d::core

/// Registers scene class `Type` in `registry` under its own name as written (`#Type`), e.g.
/// `E2D_REGISTER_SCENE(registry, MenuScene);` registers "MenuScene".
#define E2D_REGISTER_SCENE(registry, Type) (registry).add<Type>(#Type)
