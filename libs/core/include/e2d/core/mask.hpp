// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace e2d::core {

/// A set of up to 64 group bits (collision layers, ray cast filters, ...).
///
/// Two masks match when they share at least one bit. `a + b` (or `a | b`) is the union: it
/// matches everything `a` or `b` matches.
class Mask {
public:
    /// The empty mask, which matches nothing.
    constexpr Mask() noexcept = default;
    constexpr explicit Mask(std::uint64_t bits) noexcept : bits_(bits) {}

    /// Every bit set: matches every non-empty mask.
    [[nodiscard]] static constexpr Mask all() noexcept { return Mask(~std::uint64_t{0}); }

    [[nodiscard]] constexpr std::uint64_t bits() const noexcept { return bits_; }
    [[nodiscard]] constexpr bool empty() const noexcept { return bits_ == 0; }
    /// True when the two masks share at least one bit.
    [[nodiscard]] constexpr bool matches(Mask other) const noexcept {
        return (bits_ & other.bits_) != 0;
    }

    [[nodiscard]] constexpr Mask operator+(Mask other) const noexcept {
        return Mask(bits_ | other.bits_);
    }
    [[nodiscard]] constexpr Mask operator|(Mask other) const noexcept {
        return Mask(bits_ | other.bits_);
    }
    constexpr Mask& operator+=(Mask other) noexcept {
        bits_ |= other.bits_;
        return *this;
    }
    constexpr Mask& operator|=(Mask other) noexcept {
        bits_ |= other.bits_;
        return *this;
    }
    friend constexpr bool operator==(Mask, Mask) noexcept = default;

private:
    std::uint64_t bits_ = 0;
};

/// Names masks: each new name gets the next free bit, 64 at most.
class MaskRegistry {
public:
    /// How many distinct masks a registry can create.
    static constexpr int kMaxMasks = 64;

    /// The mask named `name`, creating it with the next bit if it does not exist yet.
    /// Throws core::Error for an empty name or when all 64 bits are taken.
    Mask create(std::string_view name);
    /// The mask named `name`; throws core::Error naming it if it was never created.
    [[nodiscard]] Mask get(std::string_view name) const;
    [[nodiscard]] bool contains(std::string_view name) const;
    /// Number of masks created so far.
    [[nodiscard]] int size() const noexcept { return static_cast<int>(masks_.size()); }

private:
    std::map<std::string, Mask, std::less<>> masks_;
};

} // namespace e2d::core
