// SPDX-License-Identifier: MIT
#pragma once

#include <bit>
#include <cstdint>

namespace e2d::render::detail {

// IEEE 754 binary16 from binary32, round to nearest even; overflow gives infinity, NaN stays
// NaN, tiny values become subnormals or zero. Portable (no F16C): it runs only when a sprite's
// shape changes, not per frame.
inline std::uint16_t toHalf(float value) {
    std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    std::uint32_t sign = (bits >> 16) & 0x8000u;
    std::uint32_t magnitude = bits & 0x7fffffffu;
    if (magnitude >= 0x7f800000u) { // inf or NaN
        return static_cast<std::uint16_t>(sign | 0x7c00u | (magnitude > 0x7f800000u ? 0x200u : 0u));
    }
    if (magnitude >= 0x477ff000u) { // rounds to >= 65520: overflow
        return static_cast<std::uint16_t>(sign | 0x7c00u);
    }
    if (magnitude < 0x38800000u) { // below the smallest normal half: subnormal or zero
        if (magnitude < 0x33000000u) {
            return static_cast<std::uint16_t>(sign);
        }
        std::uint32_t mantissa = (magnitude & 0x007fffffu) | 0x00800000u;
        // value = mantissa * 2^(exponent - 150); the half subnormal unit is 2^-24.
        std::uint32_t exponent = magnitude >> 23;
        int shift = static_cast<int>(126 - exponent);
        std::uint32_t half = mantissa >> shift;
        std::uint32_t rest = mantissa & ((1u << shift) - 1u);
        std::uint32_t halfway = 1u << (shift - 1);
        if (rest > halfway || (rest == halfway && (half & 1u) != 0u)) {
            ++half;
        }
        return static_cast<std::uint16_t>(sign | half);
    }
    // Normal: rebias the exponent (127 -> 15) and round the 13 dropped mantissa bits.
    std::uint32_t half = (magnitude - 0x38000000u) >> 13;
    std::uint32_t rest = magnitude & 0x1fffu;
    if (rest > 0x1000u || (rest == 0x1000u && (half & 1u) != 0u)) {
        ++half;
    }
    return static_cast<std::uint16_t>(sign | half);
}

inline float fromHalf(std::uint16_t half) {
    std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
    std::uint32_t exponent = (half >> 10) & 0x1fu;
    std::uint32_t mantissa = half & 0x3ffu;
    if (exponent == 0) {
        float value = static_cast<float>(mantissa) * (1.0f / 16777216.0f);
        return sign != 0 ? -value : value;
    }
    if (exponent == 31) {
        return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
    }
    return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
}

} // namespace e2d::render::detail
