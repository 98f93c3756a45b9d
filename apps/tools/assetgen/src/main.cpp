// SPDX-License-Identifier: MIT
// e2d_assetgen: paints the apps' images and synthesises their sounds at build time.
//   e2d_assetgen <set> <folder>   writes the files of one asset set into <folder>
//   e2d_assetgen --list           names every set
#include "asset_set.hpp"

#include <e2d/core/error.hpp>

#include <iostream>

namespace e2d::assetgen {

void Registry::add(AssetSet set) {
    if (find(set.name) != nullptr) {
        throw core::Error("assetgen::Registry::add(): a set called '" + set.name + "' exists");
    }
    sets_.push_back(std::move(set));
}

const AssetSet* Registry::find(const std::string& name) const {
    for (const AssetSet& s : sets_) {
        if (s.name == name) {
            return &s;
        }
    }
    return nullptr;
}

// One declaration per apps/assetgen/<app>.cpp (the list is written by CMake).
#define E2D_ASSETGEN_SOURCE(app) void register_##app(Registry&);
#include "asset_sources.inc"
#undef E2D_ASSETGEN_SOURCE

} // namespace e2d::assetgen

int main(int argc, char** argv) {
    using namespace e2d::assetgen;
    Registry registry;
#define E2D_ASSETGEN_SOURCE(app) register_##app(registry);
#include "asset_sources.inc"
#undef E2D_ASSETGEN_SOURCE

    const std::string usage = "usage: e2d_assetgen <set> <folder> | --list";
    if (argc == 2 && std::string(argv[1]) == "--list") {
        for (const AssetSet& s : registry.sets()) {
            std::cout << s.name << "\t" << s.description << "\n";
        }
        return 0;
    }
    if (argc != 3) {
        std::cerr << usage << "\n";
        return 2;
    }
    const AssetSet* set = registry.find(argv[1]);
    if (set == nullptr) {
        std::cerr << "e2d_assetgen: no asset set called '" << argv[1] << "' (--list names them)\n";
        return 2;
    }
    try {
        const std::filesystem::path folder = argv[2];
        std::filesystem::create_directories(folder);
        set->generate(folder);
    } catch (const std::exception& e) {
        std::cerr << "e2d_assetgen: set '" << set->name << "': " << e.what() << "\n";
        return 1;
    }
    return 0;
}
