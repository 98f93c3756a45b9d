// SPDX-License-Identifier: MIT
// World::createChain(): a chain of one-sided ChainSegment shapes through a list of points, each
// segment knowing its neighbours (ghost points) so that shapes slide smoothly along it.
#include <e2d/physics/world.hpp>

#include "world_check.hpp"
#include "world_impl.hpp"

#include <cstddef>
#include <string>

namespace e2d::physics {

namespace check = detail::world_check;

namespace {

constexpr const char* kFunction = "createChain";

void requireRestitution(const char* name, float value) {
    if (!(isFinite(value) && value >= 0.0f && value <= 1.0f)) {
        check::fail(kFunction,
                    std::string(name) + " must be finite and in [0, 1], got " + check::text(value));
    }
}

void validateChainDef(const ChainDef& def) {
    const std::size_t n = def.points.size();
    const std::size_t minimum = def.isLoop ? 3 : 2;
    if (n < minimum) {
        check::fail(kFunction, std::string("def.points must hold at least ") +
                                   std::to_string(minimum) +
                                   (def.isLoop ? " points for a loop" : " points") + ", got " +
                                   std::to_string(n));
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::string name = "def.points[" + std::to_string(i) + "]";
        check::requirePosition(kFunction, name.c_str(), def.points[i]);
    }
    const std::size_t segments = def.isLoop ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t j = (i + 1) % n;
        const float gap = distance(def.points[i], def.points[j]);
        if (!(gap >= kLinearSlop)) {
            check::fail(kFunction, "def.points[" + std::to_string(i) + "] and def.points[" +
                                       std::to_string(j) + "] must be at least kLinearSlop (" +
                                       check::text(kLinearSlop) + " m) apart, got " +
                                       check::text(gap));
        }
    }
    if (def.ghostBefore) {
        check::requirePosition(kFunction, "def.ghostBefore", *def.ghostBefore);
    }
    if (def.ghostAfter) {
        check::requirePosition(kFunction, "def.ghostAfter", *def.ghostAfter);
    }
    if (def.isLoop && (def.ghostBefore || def.ghostAfter)) {
        check::fail(kFunction,
                    "a loop has no ends: def.ghostBefore and def.ghostAfter must be empty");
    }
    const std::size_t materials = def.materials.size();
    if (materials > 1 && materials != segments) {
        check::fail(kFunction, "def.materials must hold 0, 1 or one per segment (" +
                                   std::to_string(segments) + ") materials, got " +
                                   std::to_string(materials));
    }
    for (std::size_t i = 0; i < materials; ++i) {
        const SurfaceMaterial& m = def.materials[i];
        const std::string prefix = "def.materials[" + std::to_string(i) + "].";
        check::requireNonNegative(kFunction, (prefix + "friction").c_str(), m.friction);
        requireRestitution((prefix + "restitution").c_str(), m.restitution);
        check::requireNonNegative(kFunction, (prefix + "rollingResistance").c_str(),
                                  m.rollingResistance);
    }
    check::requireNonNegative(kFunction, "def.shape.friction", def.shape.friction);
    requireRestitution("def.shape.restitution", def.shape.restitution);
    check::requireNonNegative(kFunction, "def.shape.rollingResistance",
                              def.shape.rollingResistance);
}

} // namespace

std::vector<ShapeId> World::createChain(BodyId body, const ChainDef& def) {
    impl_->requireUnlocked(kFunction);
    impl_->require(body, kFunction);
    validateChainDef(def);
    const std::vector<Vec2>& p = def.points;
    const std::size_t n = p.size();
    const std::size_t segments = def.isLoop ? n : n - 1;
    std::vector<ShapeId> ids;
    ids.reserve(segments);
    try {
        for (std::size_t i = 0; i < segments; ++i) {
            ChainSegment g;
            g.segment = {p[i], p[(i + 1) % n]};
            if (def.isLoop) {
                g.ghost1 = p[(i + n - 1) % n];
                g.ghost2 = p[(i + 2) % n];
                g.hasGhost1 = g.hasGhost2 = true;
            } else {
                g.hasGhost1 = i > 0 || def.ghostBefore.has_value();
                g.ghost1 = i > 0 ? p[i - 1] : def.ghostBefore.value_or(Vec2{0.0f, 0.0f});
                g.hasGhost2 = i + 2 < n || def.ghostAfter.has_value();
                g.ghost2 = i + 2 < n ? p[i + 2] : def.ghostAfter.value_or(Vec2{0.0f, 0.0f});
            }
            ShapeDef sd = def.shape;
            sd.density = 0.0f;
            if (!def.materials.empty()) {
                const SurfaceMaterial& m = def.materials[def.materials.size() == 1 ? 0 : i];
                sd.friction = m.friction;
                sd.restitution = m.restitution;
                sd.rollingResistance = m.rollingResistance;
                sd.userData = m.userData;
            }
            ids.push_back(createShape(body, sd, g));
        }
    } catch (...) {
        // Leave the world as it was: no half chain.
        for (ShapeId id : ids) {
            destroyShape(id);
        }
        throw;
    }
    return ids;
}

} // namespace e2d::physics
