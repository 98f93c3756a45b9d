// SPDX-License-Identifier: MIT
#include "stderr_capture.hpp"

#include <unistd.h>

namespace e2d::audio::detail {

StderrCapture::StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    if (file_ == nullptr) {
        return;
    }
    saved_ = ::dup(STDERR_FILENO);
    if (saved_ < 0 || ::dup2(::fileno(file_), STDERR_FILENO) < 0) {
        if (saved_ >= 0) {
            ::close(saved_);
            saved_ = -1;
        }
        std::fclose(file_);
        file_ = nullptr;
    }
}

StderrCapture::~StderrCapture() {
    if (file_ != nullptr) {
        writeToStderr(finish());
    }
}

std::string StderrCapture::finish() {
    if (file_ == nullptr) {
        return {};
    }
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
    std::string text;
    std::rewind(file_);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof(buffer), file_)) > 0;) {
        text.append(buffer, n);
    }
    std::fclose(file_);
    file_ = nullptr;
    return text;
}

void writeToStderr(const std::string& text) {
    if (!text.empty()) {
        std::fwrite(text.data(), 1, text.size(), stderr);
        std::fflush(stderr);
    }
}

} // namespace e2d::audio::detail
