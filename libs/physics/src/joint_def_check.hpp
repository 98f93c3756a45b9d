// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/joint.hpp>

namespace e2d::physics::detail {

// Checks every field of `def` but the bodies, as World::createJoint() does; throws its
// core::Error ("physics::World::createJoint(): <type> def.<field> ...") for the first bad one.
void validateJointDef(const JointDef& def);

} // namespace e2d::physics::detail
