// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>

namespace e2d::core {

/// The one exception type e2d throws for bad input at an API boundary.
///
/// The message names the function and the offending value, e.g.
/// `"physics::makePolygon(): expected at least 3 distinct points, got 2"`.
/// Whatever threw it left the object it was called on unchanged.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace e2d::core
