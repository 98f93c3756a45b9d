// SPDX-License-Identifier: MIT
#pragma once

#include <cstdio>
#include <string>

namespace e2d::audio::detail {

/// Holds what the process writes to its standard error (file descriptor 2) while it lives, so
/// that the messages ALSA and OpenAL Soft print there while a device is opened (eight lines
/// and more when there is no sound card) can be turned into one line of the mixer's log.
///
/// While it lives, the whole process writes into a temporary file instead: keep it to the one
/// call it is for. What finish() returns is the caller's to pass on; anything not taken (an
/// exception, or the object destroyed without finish()) is written back to standard error, so
/// nothing is lost. Does nothing (finish() returns "") where descriptors cannot be redirected.
class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// Restores standard error and returns what was written to it meanwhile.
    std::string finish();

private:
    std::FILE* file_ = nullptr;
    int saved_ = -1;
};

/// Writes `text` to standard error as it is.
void writeToStderr(const std::string& text);

} // namespace e2d::audio::detail
