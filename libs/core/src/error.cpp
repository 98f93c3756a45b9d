// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
