// SPDX-License-Identifier: MIT
#pragma once

namespace e2d::engine {

/// Colours of the physics debug draw (GameSystem::setDebugDraw(), config debugDraw, the
/// debugDrawKey), RGBA in [0, 1]. In an 8-bit screenshot a colour c reads round(255 * c), e.g.
/// a static shape's outline (0.3, 0.9, 0.35) reads (77, 230, 89). Outlines are 2 px wide,
/// AABBs 1 px, contact points 4 px dots with 20 px normals. Joints: 2 px lines from body A's
/// origin to its anchor, between the anchors and from there to body B's origin, 3 px dots on
/// the anchors, and a prismatic or wheel joint's axis through anchor A (1 px; between the
/// limits when they are on, else 30 px each way).
struct DebugDrawColors {
    static constexpr float kDynamic[4] = {0.95f, 0.75f, 0.2f, 1.0f};   ///< awake dynamic bodies
    static constexpr float kSleeping[4] = {0.55f, 0.55f, 0.55f, 1.0f}; ///< sleeping dynamic bodies
    static constexpr float kStatic[4] = {0.3f, 0.9f, 0.35f, 1.0f};     ///< static bodies
    static constexpr float kKinematic[4] = {0.35f, 0.6f, 1.0f, 1.0f};  ///< kinematic bodies
    static constexpr float kSensor[4] = {0.9f, 0.3f, 0.9f, 1.0f};      ///< sensor shapes (triggers)
    static constexpr float kAabb[4] = {1.0f, 0.2f, 0.2f, 0.6f};        ///< shapes' bounding boxes
    static constexpr float kContact[4] = {1.0f, 0.1f, 0.1f, 1.0f};     ///< touching contact points
    static constexpr float kNormal[4] = {1.0f, 1.0f, 1.0f, 1.0f};      ///< contact normals (A to B)
    static constexpr float kJoint[4] = {0.1f, 0.85f, 0.85f, 1.0f}; ///< joints: anchors and lines
};

} // namespace e2d::engine
