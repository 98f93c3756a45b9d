// SPDX-License-Identifier: MIT
#include "al_device.hpp"

#include "stderr_capture.hpp"

#include <string_view>

namespace e2d::audio::detail {

namespace {

template <class Fn>
Fn alcProc(ALCdevice* device, const char* name) {
    return reinterpret_cast<Fn>(alcGetProcAddress(device, name));
}

template <class Fn>
Fn alProc(const char* name) {
    return reinterpret_cast<Fn>(alGetProcAddress(name));
}

// What OpenAL Soft and the ALSA library it loads printed while a device failed to open: their
// lines go to `lines` (for the mixer's debug log), the reason OpenAL Soft gave (its last error
// line, without its prefix and function name) is returned, and lines from anyone else are
// written back to standard error.
std::string sortFailureOutput(const std::string& text, std::vector<std::string>& lines) {
    std::string reason;
    std::string others;
    for (std::size_t begin = 0; begin < text.size();) {
        std::size_t end = text.find('\n', begin);
        end = end == std::string::npos ? text.size() : end;
        const std::string_view line(text.data() + begin, end - begin);
        begin = end + 1;
        // OpenAL Soft 1.19 writes "AL lib: (EE) function: message", later ones "[ALSOFT] (EE) message".
        const bool openal = line.starts_with("AL lib: ") || line.starts_with("[ALSOFT] ");
        if (!openal && !line.starts_with("ALSA lib ")) {
            others.append(line).append("\n");
            continue;
        }
        lines.emplace_back(line);
        if (const std::size_t at = line.find("(EE) "); openal && at != std::string_view::npos) {
            std::string_view message = line.substr(at + 5);
            if (const std::size_t colon = message.find(": ");
                colon != std::string_view::npos &&
                message.substr(0, colon).find(' ') == std::string_view::npos) {
                message.remove_prefix(colon + 2);
            }
            reason = message;
        }
    }
    writeToStderr(others);
    return reason;
}

} // namespace

std::unique_ptr<Device> Device::openDevice(const std::string& name, int sources, std::string& error,
                                           std::vector<std::string>& libraryLines) {
    std::unique_ptr<Device> device(new Device());
    // Without a sound card, ALSA and OpenAL Soft print eight lines and more to stderr here; one
    // line of the mixer's log says it (their lines go to its debug level). When a device opens,
    // whatever they printed is passed on untouched.
    StderrCapture capture;
    device->device_ = alcOpenDevice(name.empty() ? nullptr : name.c_str());
    const std::string printed = capture.finish();
    if (device->device_ != nullptr) {
        writeToStderr(printed);
    } else {
        const std::string reason = sortFailureOutput(printed, libraryLines);
        error = name.empty() ? "no default audio device" : "no audio device named '" + name + "'";
        if (!reason.empty()) {
            error += " (OpenAL Soft: " + reason + ")";
        }
        return nullptr;
    }
    const ALCchar* opened = alcGetString(device->device_, ALC_ALL_DEVICES_SPECIFIER);
    if (opened == nullptr) {
        opened = alcGetString(device->device_, ALC_DEVICE_SPECIFIER);
    }
    device->name_ = opened != nullptr ? opened : name;
    const ALCint attributes[] = {ALC_MONO_SOURCES, sources, ALC_STEREO_SOURCES, 0, 0};
    if (!device->finishOpen(attributes, error)) {
        return nullptr;
    }
    return device;
}

std::unique_ptr<Device> Device::openLoopback(int sampleRate, int sources, ALCdevice* given,
                                             std::string& error) {
    auto open = alcProc<LPALCLOOPBACKOPENDEVICESOFT>(nullptr, "alcLoopbackOpenDeviceSOFT");
    if (alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") == ALC_FALSE || open == nullptr) {
        error = "the OpenAL implementation has no loopback device (ALC_SOFT_loopback)";
        return nullptr;
    }
    std::unique_ptr<Device> device(new Device());
    device->loopback_ = true;
    device->name_ = given != nullptr ? "caller's loopback" : "loopback";
    device->ownsDevice_ = given == nullptr;
    device->device_ = given != nullptr ? given : open(nullptr);
    if (device->device_ == nullptr) {
        error = "cannot open the loopback device";
        return nullptr;
    }
    device->renderSamples_ =
        alcProc<LPALCRENDERSAMPLESSOFT>(device->device_, "alcRenderSamplesSOFT");
    const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                                 ALC_STEREO_SOFT,
                                 ALC_FORMAT_TYPE_SOFT,
                                 ALC_FLOAT_SOFT,
                                 ALC_FREQUENCY,
                                 sampleRate,
                                 ALC_HRTF_SOFT,
                                 ALC_FALSE,
                                 ALC_MONO_SOURCES,
                                 sources,
                                 ALC_STEREO_SOURCES,
                                 0,
                                 0};
    if (!device->finishOpen(attributes, error)) {
        return nullptr;
    }
    return device;
}

bool Device::finishOpen(const ALCint* attributes, std::string& error) {
    context_ = alcCreateContext(device_, attributes);
    if (context_ == nullptr) {
        error = "cannot create an OpenAL context on '" + name_ + "' (ALC error " +
                std::to_string(alcGetError(device_)) + ")";
        return false;
    }
    if (alcIsExtensionPresent(device_, "ALC_EXT_thread_local_context") == ALC_TRUE) {
        setThreadContext_ = alcProc<PFNALCSETTHREADCONTEXTPROC>(device_, "alcSetThreadContext");
        getThreadContext_ = alcProc<PFNALCGETTHREADCONTEXTPROC>(device_, "alcGetThreadContext");
    }
    hasDisconnect_ = alcIsExtensionPresent(device_, "ALC_EXT_disconnect") == ALC_TRUE;
    makeCurrent();
    ALCint frequency = 0;
    alcGetIntegerv(device_, ALC_FREQUENCY, 1, &frequency);
    sampleRate_ = frequency;
    if (alIsExtensionPresent("AL_SOFT_deferred_updates") == AL_TRUE) {
        deferUpdates_ = alProc<LPALDEFERUPDATESSOFT>("alDeferUpdatesSOFT");
        processUpdates_ = alProc<LPALPROCESSUPDATESSOFT>("alProcessUpdatesSOFT");
    }
    // The mixer computes attenuation and panning itself (the seed's model); OpenAL must not
    // add its own distance attenuation.
    alDistanceModel(AL_NONE);
    alListener3f(AL_POSITION, 0.0f, 0.0f, 0.0f);
    alListenerf(AL_GAIN, 1.0f);
    return true;
}

Device::~Device() {
    if (context_ != nullptr) {
        if (getThreadContext_ != nullptr && getThreadContext_() == context_) {
            setThreadContext_(nullptr);
        }
        if (alcGetCurrentContext() == context_) {
            alcMakeContextCurrent(nullptr);
        }
        alcDestroyContext(context_);
    }
    if (device_ != nullptr && ownsDevice_) {
        alcCloseDevice(device_);
    }
}

void Device::makeCurrent() const {
    if (setThreadContext_ != nullptr) {
        if (getThreadContext_() != context_) {
            setThreadContext_(context_);
        }
    } else if (alcGetCurrentContext() != context_) {
        alcMakeContextCurrent(context_);
    }
}

bool Device::connected() const {
    if (!hasDisconnect_ || loopback_) {
        return true;
    }
    ALCint value = ALC_TRUE;
    alcGetIntegerv(device_, ALC_CONNECTED, 1, &value);
    return value != ALC_FALSE;
}

void Device::render(float* out, int frames) const { renderSamples_(device_, out, frames); }

void Device::deferUpdates() const {
    if (deferUpdates_ != nullptr) {
        deferUpdates_();
    }
}

void Device::processUpdates() const {
    if (processUpdates_ != nullptr) {
        processUpdates_();
    }
}

} // namespace e2d::audio::detail
