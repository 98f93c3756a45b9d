// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace e2d::assetgen {

/// A named group of assets one app needs, written into one folder.
struct AssetSet {
    /// What `e2d_assetgen <name> <folder>` calls it, e.g. "sprites".
    std::string name;
    /// One line for `e2d_assetgen --list`.
    std::string description;
    /// Writes every file of the set into `folder` (which exists).
    std::function<void(const std::filesystem::path& folder)> generate;
};

/// The sets the tool knows. Each `apps/assetgen/<app>.cpp` defines
/// `void register_<app>(Registry&)`, which CMake finds by the file's name.
class Registry {
public:
    /// Adds `set`. Throws core::Error if a set of that name exists.
    void add(AssetSet set);
    /// The set called `name`, or nullptr.
    [[nodiscard]] const AssetSet* find(const std::string& name) const;
    [[nodiscard]] const std::vector<AssetSet>& sets() const noexcept { return sets_; }

private:
    std::vector<AssetSet> sets_;
};

} // namespace e2d::assetgen
