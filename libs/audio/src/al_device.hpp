// SPDX-License-Identifier: MIT
#pragma once

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <memory>
#include <string>
#include <vector>

namespace e2d::audio::detail {

/// An OpenAL device with one context: a real device or OpenAL Soft's loopback device. The
/// context is made current per thread (ALC_EXT_thread_local_context), so several mixers can
/// live in one process.
class Device {
public:
    /// Opens the device `name` (empty: the default one) with room for `sources` mono sources.
    /// Null, and `error` says why in one line, when there is no such device or no context;
    /// then `libraryLines` gets what OpenAL Soft and ALSA printed to stderr meanwhile (kept off
    /// stderr: see StderrCapture).
    static std::unique_ptr<Device> openDevice(const std::string& name, int sources,
                                              std::string& error,
                                              std::vector<std::string>& libraryLines);
    /// A loopback device mixing stereo floats at `sampleRate` Hz: `given` (not owned: never
    /// closed here) or, when null, one opened (and closed) here.
    static std::unique_ptr<Device> openLoopback(int sampleRate, int sources, ALCdevice* given,
                                                std::string& error);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    /// Makes this device's context the calling thread's context (cheap when it already is).
    void makeCurrent() const;
    [[nodiscard]] bool isLoopback() const noexcept { return loopback_; }
    [[nodiscard]] int sampleRate() const noexcept { return sampleRate_; }
    /// False once the device was lost (ALC_EXT_disconnect); always true without that extension.
    [[nodiscard]] bool connected() const;
    /// Loopback only: mixes `frames` stereo float frames into `out`.
    void render(float* out, int frames) const;
    /// Batch the property changes that follow until processUpdates() (AL_SOFT_deferred_updates),
    /// so the mixer sees all of a frame's changes at once.
    void deferUpdates() const;
    void processUpdates() const;
    [[nodiscard]] const std::string& name() const noexcept { return name_; }

private:
    Device() = default;
    bool finishOpen(const ALCint* attributes, std::string& error);

    ALCdevice* device_ = nullptr;
    ALCcontext* context_ = nullptr;
    bool loopback_ = false;
    bool ownsDevice_ = true;
    bool hasDisconnect_ = false;
    int sampleRate_ = 0;
    std::string name_;
    LPALCRENDERSAMPLESSOFT renderSamples_ = nullptr;
    PFNALCSETTHREADCONTEXTPROC setThreadContext_ = nullptr;
    PFNALCGETTHREADCONTEXTPROC getThreadContext_ = nullptr;
    LPALDEFERUPDATESSOFT deferUpdates_ = nullptr;
    LPALPROCESSUPDATESSOFT processUpdates_ = nullptr;
};

} // namespace e2d::audio::detail
