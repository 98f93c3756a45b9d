// SPDX-License-Identifier: MIT
// A loopback device opened by the caller: the mixer plays on it and leaves it open.
#include "audio_test_support.hpp"

#include <e2d/core/error.hpp>

#include <AL/alc.h>
#include <AL/alext.h>

#include <gtest/gtest.h>

namespace e2d::audio {
namespace {

using namespace test;

TEST(CallerLoopback, MixerPlaysOnItAndLeavesItOpen) {
    useNullDriver();
    auto open = reinterpret_cast<LPALCLOOPBACKOPENDEVICESOFT>(
        alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
    auto renderSamples = reinterpret_cast<LPALCRENDERSAMPLESSOFT>(
        alcGetProcAddress(nullptr, "alcRenderSamplesSOFT"));
    ASSERT_NE(open, nullptr);
    ALCdevice* device = open(nullptr);
    ASSERT_NE(device, nullptr);
    std::vector<float> out(2 * 4800);
    {
        MixerDef def;
        def.output = Output::Loopback;
        def.loopbackDevice = device;
        def.loopbackSampleRate = 44100;
        Mixer mixer(def);
        ASSERT_TRUE(mixer.hasDevice());
        EXPECT_EQ(mixer.sampleRate(), 44100);
        SoundData tone;
        tone.channels = 1;
        tone.sampleRate = 44100;
        tone.samples = sine(1000.0, 0.5, 44100, 0.5f);
        PlayDef play;
        play.spatial = true;
        play.attenuationFactor = 0.0f;
        play.position = {-100.0f, 0.0f};
        mixer.play(mixer.add(tone), play);
        mixer.update(0.0);
        renderSamples(device, out.data(), 4800); // the caller renders by itself
        const ChannelRms r = rms(out, 441, 4800);
        EXPECT_NEAR(r.left, sineRms(0.5), 0.005);
        EXPECT_LT(r.right, 1e-4);
        ASSERT_TRUE(mixer.reopen()); // a new context on the same device
        EXPECT_TRUE(mixer.hasDevice());
    }
    // The mixer is gone, its context too; the device is still the caller's to close.
    EXPECT_EQ(alcCloseDevice(device), ALC_TRUE);
}

TEST(CallerLoopback, OnlyWithLoopbackOutput) {
    useNullDriver();
    MixerDef def;
    def.output = Output::None;
    int dummy = 0;
    def.loopbackDevice = &dummy;
    EXPECT_THROW(Mixer m(def), core::Error);
}

} // namespace
} // namespace e2d::audio
