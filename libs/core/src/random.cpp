// SPDX-License-Identifier: MIT
#include <e2d/core/random.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <cmath>
#include <string>

namespace e2d::core {

Random::Random(std::uint64_t seed) : engine_(seed) {}

void Random::seed(std::uint64_t seed) { engine_.seed(seed); }

int Random::range(int min, int max) {
    if (min > max) {
        throw Error("core::Random::range(): min must be <= max, got min " + std::to_string(min) +
                    ", max " + std::to_string(max));
    }
    // span <= 2^32, so it always fits; values below 2^64 mod span are rejected so that the
    // accepted draws cover a whole number of copies of [0, span).
    const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(max) -
                                                          static_cast<std::int64_t>(min)) +
                               1;
    const std::uint64_t threshold = (0 - span) % span;
    std::uint64_t draw = engine_();
    while (draw < threshold) {
        draw = engine_();
    }
    return static_cast<int>(static_cast<std::int64_t>(min) +
                            static_cast<std::int64_t>(draw % span));
}

float Random::range01() {
    // The top 24 bits fill a float mantissa exactly: k * 2^-24 for k in [0, 2^24).
    return static_cast<float>(engine_() >> 40) * 0x1.0p-24f;
}

float Random::range(float min, float max) {
    if (!std::isfinite(min) || !std::isfinite(max) || min > max) {
        throw Error("core::Random::range(): bounds must be finite with min <= max, got min " +
                    formatNumber(min) + ", max " + formatNumber(max));
    }
    if (!std::isfinite(max - min)) {
        throw Error("core::Random::range(): max - min overflows a float, got min " +
                    formatNumber(min) + ", max " + formatNumber(max));
    }
    const float u = range01();
    if (min == max) {
        return min;
    }
    const auto value = static_cast<float>(
        static_cast<double>(min) + (static_cast<double>(max) - static_cast<double>(min)) * u);
    // Rounding to float can land on max when the interval is a few ulps wide.
    return value < max ? value : std::nextafter(max, min);
}

} // namespace e2d::core
