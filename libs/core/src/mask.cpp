// SPDX-License-Identifier: MIT
#include <e2d/core/mask.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

namespace e2d::core {

Mask MaskRegistry::create(std::string_view name) {
    if (name.empty()) {
        throw Error("core::MaskRegistry::create(): name must not be empty");
    }
    if (const auto it = masks_.find(name); it != masks_.end()) {
        return it->second;
    }
    if (size() >= kMaxMasks) {
        throw Error("core::MaskRegistry::create(): cannot create mask " + quote(name) +
                    ", the limit of " + std::to_string(kMaxMasks) + " masks is reached");
    }
    const Mask mask(std::uint64_t{1} << masks_.size());
    masks_.emplace(std::string(name), mask);
    return mask;
}

Mask MaskRegistry::get(std::string_view name) const {
    const auto it = masks_.find(name);
    if (it == masks_.end()) {
        throw Error("core::MaskRegistry::get(): no mask named " + quote(name));
    }
    return it->second;
}

bool MaskRegistry::contains(std::string_view name) const {
    return masks_.find(name) != masks_.end();
}

} // namespace e2d::core
