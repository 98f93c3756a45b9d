// SPDX-License-Identifier: MIT
#include <e2d/audio/spatial.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace e2d::audio {

float attenuationGain(const SpatialDef& def, float distance, float factor) noexcept {
    if (factor <= 0.0f) {
        return 1.0f;
    }
    const float range = (def.maxAttenuationDistance - def.minAttenuationDistance) / factor;
    const float beyond = distance - def.minAttenuationDistance;
    if (beyond <= 0.0f) {
        return 1.0f;
    }
    if (beyond >= range) {
        return 0.0f;
    }
    return 1.0f - beyond / range;
}

StereoGains panGains(const SpatialDef& def, float offsetX) noexcept {
    const float away = std::abs(offsetX);
    float p = 0.0f;
    if (away >= def.maxPanningDistance) {
        p = 1.0f;
    } else if (away > def.minPanningDistance) {
        p = (away - def.minPanningDistance) / (def.maxPanningDistance - def.minPanningDistance);
    }
    if (offsetX < 0.0f) {
        p = -p;
    }
    const float angle = (p + 1.0f) * (std::numbers::pi_v<float> / 4.0f);
    // Exact ends: cos(pi/2) is not 0 in floats, and fully right must be silent on the left.
    if (p >= 1.0f) {
        return {0.0f, 1.0f};
    }
    if (p <= -1.0f) {
        return {1.0f, 0.0f};
    }
    return {std::cos(angle), std::sin(angle)};
}

glm::vec2 listenerSpaceOffset(glm::vec2 source, glm::vec2 listener,
                              float listenerOrientation) noexcept {
    const glm::vec2 d = source - listener;
    if (listenerOrientation == 0.0f) {
        return d;
    }
    const float c = std::cos(listenerOrientation);
    const float s = std::sin(listenerOrientation);
    return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

} // namespace e2d::audio
