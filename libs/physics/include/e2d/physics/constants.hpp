// SPDX-License-Identifier: MIT
#pragma once

/// Tuning constants shared by collision and dynamics. Lengths are in metres: e2d is tuned for
/// moving objects of 0.1 m to 10 m, like Box2D. Scale game units to metres at the boundary.
namespace e2d::physics {

/// The most vertices a convex polygon may have.
inline constexpr int kMaxPolygonVertices = 8;
/// Collision and constraint tolerance, metres. Points closer than this are welded by the hull.
inline constexpr float kLinearSlop = 0.005f;
/// Default margin within which not-yet-touching points are reported in a manifold, metres.
inline constexpr float kSpeculativeDistance = 4.0f * kLinearSlop;
/// How far the broad phase fattens a moving shape's box, metres.
inline constexpr float kAabbMargin = 0.1f;
/// Coordinates beyond this magnitude are rejected, metres (500 km; sizes and densities too, in
/// metres and kg/m^2). A body whose origin a step carries beyond it is disabled and reported
/// (World::outOfRangeBodies()). The solver's precision does not depend on the distance to the
/// origin (it works from each body's motion since the start of the step, and keeps the motion
/// below the float resolution), but positions are floats: between 262 144 and 524 288 m a
/// float step is 3.1 cm (7.8 mm at 100 km, 6.3 cm at 1 000 km). The narrow phase sees each
/// shape where its float position is, up to half a step (1.6 cm) from where it is, which stays
/// inside the speculative margin (kSpeculativeDistance, 2 cm): a pile out there still finds
/// every contact it has at the origin. The base-10 pyramid comes to rest at (495 000,
/// -400 000) as at the origin (the validation's far_pyramid is at 100 km), and did still at
/// 8 000 km; beyond 500 km the reported positions are too coarse for objects of 0.1 m.
inline constexpr float kHuge = 500000.0f;
/// The longest time step World::step() takes, seconds. Longer steps are rejected: the soft
/// contacts sag by about gravity * (step / sub-steps)^2, so a resting box sinks 3 mm into the
/// floor at 0.25 s, 3 cm at 1 s and falls through at 5 s. A game loop that falls behind calls
/// step() several times, or drops time, rather than stepping once by the whole frame.
inline constexpr float kMaxTimeStep = 0.25f;

} // namespace e2d::physics
