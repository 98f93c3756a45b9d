// SPDX-License-Identifier: MIT
#include "al_device.hpp"


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

} // namespace

std::unique_ptr<Device> Device::openDevice(const std::string& name, int sources, std::string& error) {
    std::unique_ptr<Device> device(new Device());
    device->device_ = alcOpenDevice(name.empty() ? nullptr : name.c_str());
    if (device->device_ == nullptr) {
        error = name.empty() ? "no default audio device" : "no audio device named '" + name + "'";
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

std::unique_ptr<Device> Device::openLoopback(int sampleRate, int sources, ALCdevice* given, std::string& error) {
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
    device->renderSamples_ = alcProc<LPALCRENDERSAMPLESSOFT>(device->device_, "alcRenderSamplesSOFT");
    const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT, ALC_STEREO_SOFT,
                                 ALC_FORMAT_TYPE_SOFT, ALC_FLOAT_SOFT,
                                 ALC_FREQUENCY, sampleRate,
                                 ALC_HRTF_SOFT, ALC_FALSE,
                                 ALC_MONO_SOURCES, sources,
                                 ALC_STEREO_SOURCES, 0,
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

void Device::render(float* out, int frames) const {
    renderSamples_(device_, out, frames);
}

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
