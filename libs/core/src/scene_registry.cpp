// SPDX-License-Identifier: MIT
#include <e2d/core/scene_registry.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

namespace e2d::core {

void SceneRegistry::add(std::string name, Factory factory) {
    if (name.empty()) {
        throw Error("core::SceneRegistry::add(): scene name must not be empty");
    }
    if (!factory) {
        throw Error("core::SceneRegistry::add(): factory for scene " + quote(name) + " is empty");
    }
    if (factories_.contains(name)) {
        throw Error("core::SceneRegistry::add(): a scene named " + quote(name) +
                    " is already registered");
    }
    factories_.emplace(std::move(name), std::move(factory));
}

void SceneRegistry::add(std::string name, SceneFunctions functions) {
    add(std::move(name),
        [functions = std::move(functions)] { return std::make_unique<FunctionScene>(functions); });
}

std::unique_ptr<Scene> SceneRegistry::create(std::string_view name) const {
    const auto it = factories_.find(name);
    return it != factories_.end() ? it->second() : nullptr;
}

bool SceneRegistry::contains(std::string_view name) const {
    return factories_.find(name) != factories_.end();
}

std::vector<std::string> SceneRegistry::names() const {
    std::vector<std::string> result;
    result.reserve(factories_.size());
    for (const auto& entry : factories_) {
        result.push_back(entry.first);
    }
    return result;
}

} // namespace e2d::core
