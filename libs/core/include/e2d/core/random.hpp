// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <random>

namespace e2d::core {

/// Seedable pseudo-random numbers, owned by whoever needs them (no global state).
///
/// The engine is std::mt19937_64, whose output is fixed by the standard; the mapping to
/// ranges is done here rather than with std distributions (whose results differ between
/// standard libraries), so a given seed gives the same sequence on every platform.
class Random {
public:
    /// Seeds the engine with `seed`; the same seed always gives the same sequence.
    explicit Random(std::uint64_t seed);

    /// Restarts the sequence from `seed`.
    void seed(std::uint64_t seed);

    /// Uniform integer in [min, max], both ends included, without modulo bias.
    /// `range(5, 5)` is 5; the full int range is allowed. Throws core::Error if min > max.
    int range(int min, int max);

    /// Uniform float in [min, max): min may be returned, max never (except `range(x, x)`,
    /// which returns x). Throws core::Error if min > max, either bound is not finite or
    /// max - min overflows.
    float range(float min, float max);

    /// Uniform float in [0, 1), on a grid of 2^-24 (every value exactly representable).
    float range01();

    /// Next raw 64-bit output of the engine.
    std::uint64_t next() { return engine_(); }

    /// The underlying engine, for use with other code that takes a URBG.
    [[nodiscard]] std::mt19937_64& engine() noexcept { return engine_; }

private:
    std::mt19937_64 engine_;
};

} // namespace e2d::core
