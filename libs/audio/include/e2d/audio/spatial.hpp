// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

/// The 2D spatial model: linear distance attenuation between a minimum and a maximum distance,
/// and equal-power stereo panning from the horizontal offset to the listener.
namespace e2d::audio {

/// Distances of the spatial model, in world units, shared by every voice of a mixer.
struct SpatialDef {
    /// Up to this distance from the listener a spatial voice plays at full gain. Default 1.
    float minAttenuationDistance = 1.0f;
    /// With attenuation factor 1 the gain reaches 0 here (linear in between). Default 20.
    float maxAttenuationDistance = 20.0f;
    /// Up to this horizontal offset from the listener a voice plays centred. Default 1.
    float minPanningDistance = 1.0f;
    /// From this horizontal offset on a voice plays fully left or fully right. Default 10.
    float maxPanningDistance = 10.0f;
};

/// Left and right channel gains.
struct StereoGains {
    float left = 0.0f;
    float right = 0.0f;
};

/// Distance attenuation: 1 within `minAttenuationDistance`, then falling linearly to 0 at
/// `min + (max - min) / factor` and 0 beyond. `distance` is the 2D distance to the listener.
/// `factor` 0 means no attenuation (always 1); a factor of 2 halves the range.
[[nodiscard]] float attenuationGain(const SpatialDef& def, float distance, float factor) noexcept;

/// Equal-power panning of a mono voice whose horizontal offset from the listener (in the
/// listener's frame, positive to the right) is `offsetX`:
///   p = 0 for |offsetX| <= minPanningDistance, 1 for |offsetX| >= maxPanningDistance,
///   (|offsetX| - min) / (max - min) in between, signed like offsetX;
///   angle = (p + 1) * pi / 4; left = cos(angle), right = sin(angle).
/// So left^2 + right^2 = 1 everywhere: centred is 0.7071 on both channels, fully right is
/// (0, 1), halfway between min and max on the right is (0.3827, 0.9239).
[[nodiscard]] StereoGains panGains(const SpatialDef& def, float offsetX) noexcept;

/// The offset of `source` from a listener at `listener` turned by `listenerOrientation`
/// (radians, counter-clockwise), expressed in the listener's frame (x to its right).
[[nodiscard]] glm::vec2 listenerSpaceOffset(glm::vec2 source, glm::vec2 listener,
                                            float listenerOrientation) noexcept;

} // namespace e2d::audio
