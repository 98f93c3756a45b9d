// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

/// Handles to objects owned by a physics::World. A handle is a small value (8 bytes): the slot
/// index plus one (so a zero-initialised handle is null), the slot's generation, which changes
/// when the object is destroyed, and the tag of the world that handed it out (see
/// WorldDef::tag). A stale handle (its object destroyed, the slot perhaps reused) or a handle
/// from another world is detected on every use instead of reaching another object.
namespace e2d::physics {

/// A body in a World. Default-constructed: null.
struct BodyId {
    std::uint32_t index1 = 0;     ///< slot index + 1; 0 means null
    std::uint16_t generation = 0; ///< the slot's generation when the id was handed out
    std::uint16_t world = 0;      ///< the tag of the world that handed it out (never 0 when live)

    [[nodiscard]] constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(BodyId, BodyId) = default;
};

/// A shape attached to a body. Default-constructed: null.
struct ShapeId {
    std::uint32_t index1 = 0;     ///< slot index + 1; 0 means null
    std::uint16_t generation = 0; ///< the slot's generation when the id was handed out
    std::uint16_t world = 0;      ///< the tag of the world that handed it out (never 0 when live)

    [[nodiscard]] constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(ShapeId, ShapeId) = default;
};

/// A joint between two bodies. Default-constructed: null.
struct JointId {
    std::uint32_t index1 = 0;     ///< slot index + 1; 0 means null
    std::uint16_t generation = 0; ///< the slot's generation when the id was handed out
    std::uint16_t world = 0;      ///< the tag of the world that handed it out (never 0 when live)

    [[nodiscard]] constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(JointId, JointId) = default;
};

/// The null handles.
inline constexpr BodyId kNullBodyId{};
inline constexpr ShapeId kNullShapeId{};
inline constexpr JointId kNullJointId{};

} // namespace e2d::physics
