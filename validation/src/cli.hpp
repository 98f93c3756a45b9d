// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace e2d::validation {

/// Exit statuses of e2d-validate.
inline constexpr int kExitPassed = 0;   ///< every baseline check passed
inline constexpr int kExitFailed = 1;   ///< the runs completed, some check failed
inline constexpr int kExitBadInput = 2; ///< bad usage or an invalid scenario file

/// The whole program behind main(), testable: parses `args` (without the program name), runs,
/// writes the report and returns the exit status. Output goes to the given streams.
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace e2d::validation
