// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>

#include <cstdint>

/// Handles to objects owned by a physics::World (core::Id, 8 bytes): the slot index plus one
/// (so a zero-initialised handle is null), the slot's 16-bit generation, which changes when the
/// object is destroyed, and as `owner` the tag of the world that handed it out (see
/// WorldDef::tag; never 0 when live). A stale handle (its object destroyed, the slot perhaps
/// reused) or a handle from another world is detected on every use instead of reaching another
/// object.
namespace e2d::physics {

struct BodyIdTag;
struct ShapeIdTag;
struct JointIdTag;

/// A body in a World. Default-constructed: null.
using BodyId = core::Id<BodyIdTag, std::uint16_t, std::uint16_t>;
/// A shape attached to a body. Default-constructed: null.
using ShapeId = core::Id<ShapeIdTag, std::uint16_t, std::uint16_t>;
/// A joint between two bodies. Default-constructed: null.
using JointId = core::Id<JointIdTag, std::uint16_t, std::uint16_t>;

static_assert(sizeof(BodyId) == 8 && sizeof(ShapeId) == 8 && sizeof(JointId) == 8);

/// The null handles.
inline constexpr BodyId kNullBodyId{};
inline constexpr ShapeId kNullShapeId{};
inline constexpr JointId kNullJointId{};

} // namespace e2d::physics
