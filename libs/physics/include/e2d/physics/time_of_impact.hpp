// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/distance.hpp>

#include <cstdint>

/// Time of impact of two moving convex shapes, for continuous collision (bullet bodies).
namespace e2d::physics {

/// The most conservative-advancement steps timeOfImpact() runs before giving up (Failed).
inline constexpr int kMaxToiIterations = 50;

/// A body's motion over one step: its centre of mass moves linearly from c1 to c2 and its
/// rotation turns at constant angular speed from q1 to q2 (by the shortest way, so the step
/// must turn by less than pi).
struct Sweep {
    Vec2 localCenter{0.0f, 0.0f}; ///< centre of mass in the body frame, metres
    Vec2 c1{0.0f, 0.0f};          ///< world centre of mass at the start, metres
    Vec2 c2{0.0f, 0.0f};          ///< world centre of mass at the end, metres
    Rot q1{};                     ///< rotation at the start
    Rot q2{};                     ///< rotation at the end
};

/// The body transform (origin and rotation, not the centre of mass) at `t` in [0, 1].
Transform sweepTransform(const Sweep& sweep, float t);

/// Two proxies, in their body frames, and their sweeps.
struct TOIInput {
    ShapeProxy proxyA;
    ShapeProxy proxyB;
    Sweep sweepA;
    Sweep sweepB;
    float maxFraction = 1.0f; ///< end of the interval searched, in [0, 1]
};

enum class TOIState : std::uint8_t {
    Unknown,    ///< not computed
    Failed,     ///< no convergence in kMaxToiIterations; `fraction` is still safe (no overlap)
    Overlapped, ///< the core shapes overlap at the start; `fraction` is 0
    Hit,        ///< the shapes come within the target separation at `fraction`
    Separated,  ///< no contact before maxFraction; `fraction` is maxFraction
};

struct TOIOutput {
    TOIState state = TOIState::Unknown;
    float fraction = 0.0f; ///< in [0, maxFraction]
    int iterations = 0;    ///< conservative-advancement steps
};

/// First time the two shapes come within the target separation, by conservative advancement
/// (Mirtich): at each step, GJK gives the distance d and normal n of the core shapes, and time
/// advances by (d - target) / (bound on the closing speed along n, counting rotation through
/// the farthest proxy point from each centre of mass), which can never pass the contact.
/// target = max(kLinearSlop, radiusA + radiusB - kLinearSlop): the rounded shapes end just
/// overlapping, the cores never do. Hit is reported within 0.25 * kLinearSlop of the target.
/// Fast spins near contact converge slowly: after kMaxToiIterations the state is Failed.
TOIOutput timeOfImpact(const TOIInput& input);

} // namespace e2d::physics
