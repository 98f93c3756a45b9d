// SPDX-License-Identifier: MIT
// The mixer measured through OpenAL Soft's loopback device: panning, attenuation, gains, fades,
// pause/resume, voice stealing, stale ids, validation and running without a device.
#include "audio_test_support.hpp"

#include <e2d/core/error.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace e2d::audio {
namespace {

using namespace test;
using ::testing::HasSubstr;

constexpr double kAmp = 0.5;

SpatialDef testSpatial() {
    SpatialDef s;
    s.minAttenuationDistance = 1.0f;
    s.maxAttenuationDistance = 21.0f; // range 20
    s.minPanningDistance = 2.0f;
    s.maxPanningDistance = 10.0f;
    return s;
}

MixerDef testDef() {
    MixerDef def;
    def.spatial = testSpatial();
    return def;
}

/// A looping 1 kHz tone, written as a float WAV.
SoundId loadTone(Mixer& mixer) {
    const auto path = writeSound("tone1k.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, Rig::kRate,
                                 sine(1000.0, 1.0, Rig::kRate, static_cast<float>(kAmp)));
    const SoundId id = mixer.load(path);
    EXPECT_TRUE(mixer.soundInfo(id).ok()) << mixer.soundInfo(id).error;
    return id;
}

/// Plays the tone at `position` (spatial) and returns the RMS of 0.05..0.45 s.
ChannelRms measureAt(glm::vec2 position, float factor, MixerDef def = testDef()) {
    Rig rig(def);
    PlayDef play;
    play.loop = true;
    play.spatial = true;
    play.position = position;
    play.attenuationFactor = factor;
    EXPECT_FALSE(rig.mixer.play(loadTone(rig.mixer), play).isNull());
    rig.mixer.update(0.0);
    const auto out = rig.render(0.45);
    return rms(out, 2400, out.size() / 2);
}

// Panning (attenuation off) -----------------------------------------------------------------

TEST(MixerPan, BeyondMaxPanningDistanceOnTheRightIsAllRight) {
    for (float x : {10.0f, 25.0f}) {
        const ChannelRms r = measureAt({x, 0.0f}, 0.0f);
        EXPECT_LT(r.left, 1e-4) << x;
        EXPECT_NEAR(r.right, sineRms(kAmp), 0.005 * sineRms(kAmp)) << x;
    }
    const ChannelRms l = measureAt({-12.0f, 3.0f}, 0.0f);
    EXPECT_LT(l.right, 1e-4);
    EXPECT_NEAR(l.left, sineRms(kAmp), 0.005 * sineRms(kAmp));
}

TEST(MixerPan, WithinMinPanningDistanceChannelsAreEqual) {
    for (float x : {0.0f, 1.5f, -2.0f}) {
        const ChannelRms r = measureAt({x, 0.0f}, 0.0f);
        EXPECT_NEAR(r.left, r.right, 1e-5) << x;
        // Equal power: each side cos(pi/4) of the tone.
        EXPECT_NEAR(r.left, sineRms(kAmp) * std::cos(std::numbers::pi / 4), 0.005 * sineRms(kAmp))
            << x;
    }
}

TEST(MixerPan, HalfwayFollowsTheEqualPowerCurve) {
    // min 2, max 10: x = 6 is p = 0.5, angle (1 + 0.5) * pi / 4.
    const double angle = 1.5 * std::numbers::pi / 4;
    const ChannelRms r = measureAt({6.0f, 0.0f}, 0.0f);
    EXPECT_NEAR(r.left, sineRms(kAmp) * std::cos(angle), 0.005 * sineRms(kAmp));
    EXPECT_NEAR(r.right, sineRms(kAmp) * std::sin(angle), 0.005 * sineRms(kAmp));
    const ChannelRms l = measureAt({-6.0f, 0.0f}, 0.0f);
    EXPECT_NEAR(l.right, sineRms(kAmp) * std::cos(angle), 0.005 * sineRms(kAmp));
    EXPECT_NEAR(l.left, sineRms(kAmp) * std::sin(angle), 0.005 * sineRms(kAmp));
}

TEST(MixerPan, ListenerOrientationTurnsTheEars) {
    // A listener turned a quarter turn counter-clockwise has its right ear pointing up (+y).
    MixerDef def = testDef();
    Rig rig(def);
    rig.mixer.setListener({0.0f, 0.0f}, static_cast<float>(std::numbers::pi / 2));
    PlayDef play;
    play.loop = true;
    play.spatial = true;
    play.attenuationFactor = 0.0f;
    play.position = {0.0f, 20.0f};
    rig.mixer.play(loadTone(rig.mixer), play);
    rig.mixer.update(0.0);
    const auto out = rig.render(0.2);
    const ChannelRms r = rms(out, 2400, out.size() / 2);
    EXPECT_LT(r.left, 1e-4);
    EXPECT_NEAR(r.right, sineRms(kAmp), 0.005 * sineRms(kAmp));
}

// Attenuation (centred, so both channels carry cos(pi/4) of the gain) -----------------------

TEST(MixerAttenuation, FullWithinMinZeroAtMaxHalfHalfway) {
    const double full = measureAt({0.0f, 0.5f}, 1.0f).left;
    EXPECT_NEAR(full, sineRms(kAmp) * std::cos(std::numbers::pi / 4), 0.005 * sineRms(kAmp));
    EXPECT_LT(measureAt({0.0f, 21.0f}, 1.0f).left, 1e-4 * full);
    EXPECT_LT(measureAt({0.0f, 30.0f}, 1.0f).left, 1e-4 * full);
    // Halfway between min (1) and max (21): 11, using the 2D distance (here along a diagonal).
    const float diagonal = 11.0f / std::numbers::sqrt2_v<float>;
    EXPECT_NEAR(measureAt({0.0f, 11.0f}, 1.0f).left / full, 0.5, 0.005);
    const ChannelRms d = measureAt({diagonal, diagonal}, 1.0f); // horizontal offset 7.8: panned
    EXPECT_NEAR(std::hypot(d.left, d.right) / (full * std::numbers::sqrt2), 0.5, 0.005);
}

TEST(MixerAttenuation, FactorTwoHalvesTheRange) {
    const double full = measureAt({0.0f, 0.0f}, 2.0f).left;
    EXPECT_LT(measureAt({0.0f, 11.0f}, 2.0f).left, 1e-4 * full); // 1 + 20 / 2
    EXPECT_NEAR(measureAt({0.0f, 6.0f}, 2.0f).left / full, 0.5, 0.005);
    EXPECT_NEAR(measureAt({0.0f, 100.0f}, 0.0f).left / full, 1.0, 0.005); // factor 0: none
}

TEST(MixerAttenuation, MovingTheListenerUpdatesPlayingVoices) {
    Rig rig(testDef());
    PlayDef play;
    play.loop = true;
    play.spatial = true;
    play.position = {0.0f, 11.0f};
    const SoundId tone = loadTone(rig.mixer);
    rig.mixer.play(tone, play);
    play.position = {0.0f, 16.0f};
    rig.mixer.play(tone, play);
    rig.mixer.update(0.0);
    const double before = rms(rig.render(0.2), 2400, 9600).left;
    rig.mixer.setListener({0.0f, 11.0f});
    rig.mixer.update(0.0);
    const double after = rms(rig.render(0.2), 2400, 9600).left;
    // Before: distances 11 and 16, gains 0.5 and 0.25 of one tone (in phase); after: distances
    // 0 and 5, gains 1 and 1 - 4/20.
    EXPECT_NEAR(after / before, (1.0 + 0.8) / (0.5 + 0.25), 0.005);
}

// Gains ---------------------------------------------------------------------------------------

TEST(MixerGain, MasterGainHalfHalvesTheRms) {
    Rig rig(testDef());
    PlayDef play;
    play.loop = true;
    rig.mixer.play(loadTone(rig.mixer), play);
    rig.mixer.update(0.0);
    const double full = rms(rig.render(0.2), 2400, 9600).left;
    rig.mixer.setMasterGain(0.5f);
    rig.mixer.update(0.0);
    const double half = rms(rig.render(0.2), 2400, 9600).left;
    EXPECT_NEAR(full, sineRms(kAmp) * std::cos(std::numbers::pi / 4), 0.005 * sineRms(kAmp));
    EXPECT_NEAR(half / full, 0.5, 0.002);
}

TEST(MixerGain, BusesScaleOnlyTheirVoices) {
    Rig rig(testDef());
    const SoundId tone = loadTone(rig.mixer);
    PlayDef music;
    music.loop = true;
    music.bus = Bus::Music;
    music.spatial = true;
    music.attenuationFactor = 0.0f;
    music.position = {-50.0f, 0.0f}; // left only
    PlayDef effect = music;
    effect.bus = Bus::Effects;
    effect.position = {50.0f, 0.0f}; // right only
    rig.mixer.play(tone, music);
    rig.mixer.play(tone, effect);
    rig.mixer.setBusGain(Bus::Music, 0.25f);
    rig.mixer.update(0.0);
    const ChannelRms r = rms(rig.render(0.2), 2400, 9600);
    EXPECT_NEAR(r.left / sineRms(kAmp), 0.25, 0.002);
    EXPECT_NEAR(r.right / sineRms(kAmp), 1.0, 0.005);
}

// Fades -----------------------------------------------------------------------------------------

TEST(MixerFade, FadeOutHalfwayIsHalfThenSilence) {
    Rig rig(testDef());
    PlayDef play;
    play.loop = true;
    const VoiceId voice = rig.mixer.play(loadTone(rig.mixer), play);
    rig.mixer.update(0.0);
    auto out = rig.render(0.2);
    const double start = rms(out, 4800, 9600).left;
    ASSERT_TRUE(rig.mixer.stop(voice, 0.5));
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Playing); // still fading
    rig.mixer.update(0.0);
    out = rig.render(0.8, 0.005);
    // Windows of 20 ms centred on 0.25 s into the fade: the gain there averages 0.5 (the mix
    // hears each update's gain from the next 5 ms block on, so it lags by up to one block).
    EXPECT_NEAR(rms(out, 12000 - 480, 12000 + 480).left / start, 0.5, 0.02);
    EXPECT_NEAR(rms(out, 6000 - 480, 6000 + 480).left / start, 0.75, 0.02);
    EXPECT_LT(rms(out, 24000 + 960, out.size() / 2).left, 1e-6); // after 0.5 s: silence
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Stopped);
    EXPECT_FALSE(rig.mixer.stop(voice));
}

TEST(MixerFade, DurationDoesNotDependOnFrameRate) {
    for (double step : {0.001, 0.016, 0.1, 0.25}) {
        Rig rig(testDef());
        PlayDef play;
        play.loop = true;
        const VoiceId voice = rig.mixer.play(loadTone(rig.mixer), play);
        rig.mixer.stop(voice, 0.5);
        double t = 0.0;
        while (t + step <= 0.25 + 1e-9) {
            rig.mixer.update(step);
            t += step;
        }
        EXPECT_NEAR(rig.mixer.effectiveGain(voice), 1.0 - t / 0.5, 1e-5) << step;
        rig.mixer.update(0.5); // one long frame past the end
        EXPECT_EQ(rig.mixer.state(voice), VoiceState::Stopped) << step;
    }
}

TEST(MixerFade, FadeInAndFadeOutToPause) {
    Rig rig(testDef());
    PlayDef play;
    play.loop = true;
    play.fadeIn = 0.4;
    const VoiceId voice = rig.mixer.play(loadTone(rig.mixer), play);
    auto out = rig.render(0.6, 0.005);
    const double full = rms(out, 24000, 28800).left;
    EXPECT_NEAR(rms(out, 9600 - 480, 9600 + 480).left / full, 0.5, 0.03); // 0.2 s of 0.4
    ASSERT_TRUE(rig.mixer.pause(voice, 0.2));
    out = rig.render(0.4, 0.005);
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Paused);
    EXPECT_NEAR(rms(out, 4800 - 480, 4800 + 480).left / full, 0.5, 0.03);
    EXPECT_LT(rms(out, 9600 + 960, out.size() / 2).left, 1e-6);
    ASSERT_TRUE(rig.mixer.resume(voice));
    rig.mixer.update(0.0);
    EXPECT_NEAR(rms(rig.render(0.1), 480, 4800).left / full, 1.0, 0.01);
}

// Pause and resume ------------------------------------------------------------------------------

TEST(MixerPause, ResumeContinuesWhereItStopped) {
    // A ramp: each sample tells where in the sound it is.
    const int frames = Rig::kRate;
    SoundData ramp;
    ramp.channels = 1;
    ramp.sampleRate = Rig::kRate;
    for (int i = 0; i < frames; ++i) {
        ramp.samples.push_back(static_cast<float>(i) / frames);
    }
    Rig rig(testDef());
    const VoiceId voice = rig.mixer.play(rig.mixer.add(ramp, "ramp"));
    rig.mixer.update(0.0);
    auto before = rig.render(0.2);
    ASSERT_TRUE(rig.mixer.pause(voice));
    const double pausedAt = rig.mixer.playbackPosition(voice);
    EXPECT_NEAR(pausedAt, 0.2, 0.001);
    const auto silence = rig.render(0.3);
    EXPECT_LT(rms(silence, 0, silence.size() / 2).left, 1e-7);
    EXPECT_NEAR(rig.mixer.playbackPosition(voice), pausedAt, 1e-9);
    ASSERT_TRUE(rig.mixer.resume(voice));
    const auto after = rig.render(0.1);
    // The first frames after the resume carry on from the last ones before the pause.
    const float gain = std::cos(std::numbers::pi_v<float> / 4);
    const float last = before[before.size() - 2] / gain;
    const float next = after[0] / gain;
    EXPECT_NEAR(next - last, 1.0f / frames, 0.5f / frames);
    EXPECT_NEAR(after[2 * 4799] / gain, last + 4800.0f / frames, 1.0f / frames);
}

// Voices ------------------------------------------------------------------------------------------

TEST(MixerVoices, StealingTakesTheQuietestOfTheLowestPriority) {
    MixerDef def = testDef();
    def.voiceCount = 3;
    Rig rig(def);
    const SoundId tone = loadTone(rig.mixer);
    PlayDef play;
    play.loop = true;
    play.priority = 1;
    play.gain = 0.1f;
    const VoiceId quietButImportant = rig.mixer.play(tone, play);
    play.priority = 0;
    play.gain = 0.8f;
    const VoiceId loud = rig.mixer.play(tone, play);
    play.gain = 0.3f;
    const VoiceId quiet = rig.mixer.play(tone, play);
    rig.mixer.update(0.0);

    // Same priority as the lowest: refused, nothing changes.
    play.priority = 0;
    EXPECT_TRUE(rig.mixer.play(tone, play).isNull());
    EXPECT_EQ(rig.mixer.stats().playsRefused, 1);

    play.priority = 1;
    play.gain = 1.0f;
    const VoiceId newcomer = rig.mixer.play(tone, play);
    ASSERT_FALSE(newcomer.isNull());
    EXPECT_EQ(rig.mixer.stats().voicesStolen, 1);
    EXPECT_EQ(rig.mixer.state(quiet), VoiceState::Stopped); // the quietest of priority 0
    EXPECT_EQ(rig.mixer.state(loud), VoiceState::Playing);
    EXPECT_EQ(rig.mixer.state(quietButImportant), VoiceState::Playing);
    EXPECT_EQ(newcomer.index1, quiet.index1); // same slot, new generation
    EXPECT_NE(newcomer.generation, quiet.generation);

    // The stale id does nothing to the voice now in its slot.
    EXPECT_FALSE(rig.mixer.stop(quiet));
    EXPECT_FALSE(rig.mixer.pause(quiet));
    EXPECT_FALSE(rig.mixer.setGain(quiet, 0.0f));
    EXPECT_FALSE(rig.mixer.setPosition(quiet, {5.0f, 5.0f}));
    EXPECT_TRUE(rig.mixer.sound(quiet).isNull());
    EXPECT_EQ(rig.mixer.state(newcomer), VoiceState::Playing);
    EXPECT_FLOAT_EQ(rig.mixer.effectiveGain(newcomer), 1.0f);
    rig.mixer.update(0.0);
    // Heard: 0.1 + 0.8 + 1.0 of the tone (in phase), centred.
    const double heard = rms(rig.render(0.1), 480, 4800).left;
    EXPECT_NEAR(heard / (sineRms(kAmp) * std::cos(std::numbers::pi / 4)), 1.9, 0.01);

    // Priority 2 steals from priority 0 first, never from above.
    play.priority = 2;
    EXPECT_FALSE(rig.mixer.play(tone, play).isNull());
    EXPECT_EQ(rig.mixer.state(loud), VoiceState::Stopped);
    EXPECT_EQ(rig.mixer.stats().voicesInUse, 3);
}

TEST(MixerVoices, FinishedVoiceFreesItsSlotAndItsIdGoesStale) {
    Rig rig(testDef());
    SoundData blip;
    blip.channels = 1;
    blip.sampleRate = Rig::kRate;
    blip.samples.assign(480, 0.25f);
    const VoiceId voice = rig.mixer.play(rig.mixer.add(blip));
    EXPECT_EQ(rig.mixer.stats().voicesInUse, 1);
    rig.render(0.05);
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Stopped);
    EXPECT_EQ(rig.mixer.stats().voicesInUse, 0);
    EXPECT_FALSE(rig.mixer.resume(voice));
    EXPECT_EQ(rig.mixer.effectiveGain(voice), 0.0f);
}

TEST(MixerVoices, StereoSoundsKeepTheirChannels) {
    Rig rig(testDef());
    const auto path = writeSound("stereo.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 2, Rig::kRate,
                                 sine(1000.0, 0.5, Rig::kRate, 0.5f, 2, 0.5f));
    PlayDef play;
    play.loop = true;
    rig.mixer.play(rig.mixer.load(path), play);
    rig.mixer.update(0.0);
    const ChannelRms r = rms(rig.render(0.2), 2400, 9600);
    EXPECT_NEAR(r.left, sineRms(0.5), 0.002);
    EXPECT_NEAR(r.right, sineRms(0.25), 0.002);
}

TEST(MixerSounds, CachedByPathAndFailedLoadsPlaySilence) {
    Rig rig(testDef());
    const SoundId a = loadTone(rig.mixer);
    const SoundId b = loadTone(rig.mixer);
    EXPECT_EQ(a, b);
    EXPECT_EQ(rig.mixer.soundCount(), 1);
    const auto missing = tempDir() / "missing.ogg";
    const SoundId bad = rig.mixer.load(missing);
    EXPECT_FALSE(rig.mixer.soundInfo(bad).ok());
    EXPECT_THAT(rig.mixer.soundInfo(bad).error, HasSubstr(missing.string()));
    EXPECT_EQ(rig.count(core::LogLevel::Error, missing.string()), 1);
    EXPECT_EQ(rig.mixer.load(missing), bad); // cached: not logged again
    EXPECT_EQ(rig.count(core::LogLevel::Error, missing.string()), 1);
    EXPECT_TRUE(rig.mixer.play(bad).isNull());
    rig.mixer.update(0.0);
    EXPECT_LT(rms(rig.render(0.05), 0, 2400).left, 1e-7);
}

TEST(MixerSounds, RealFreedesktopSoundsPlay) {
    Rig rig(testDef());
    const SoundId bell = rig.mixer.load("/usr/share/sounds/freedesktop/stereo/bell.oga");
    ASSERT_TRUE(rig.mixer.soundInfo(bell).ok()) << rig.mixer.soundInfo(bell).error;
    rig.mixer.play(bell);
    rig.mixer.update(0.0);
    const auto out = rig.render(0.3);
    EXPECT_GT(rms(out, 0, out.size() / 2).left, 0.001);
}

// Validation ------------------------------------------------------------------------------------

TEST(MixerValidation, MessagesNameFunctionFieldAndValue) {
    test::useNullDriver();
    auto message = [](auto&& call) {
        try {
            call();
        } catch (const core::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    MixerDef bad;
    bad.output = Output::None;
    bad.voiceCount = 0;
    EXPECT_EQ(message([&] { Mixer m(bad); }),
              "audio::Mixer::Mixer(): voiceCount must be in 1..1024, got 0");
    bad.voiceCount = 4;
    bad.spatial.maxPanningDistance = 0.5f;
    EXPECT_EQ(message([&] { Mixer m(bad); }), "audio::Mixer::Mixer(): spatial.maxPanningDistance "
                                              "must be > minPanningDistance (1), got 0.5");
    bad.spatial = {};
    bad.streamChunkSeconds = 0.05;
    EXPECT_THAT(message([&] { Mixer m(bad); }),
                HasSubstr("(streamChunkCount - 1) * streamChunkSeconds must be >= 0.25 s"));

    Rig rig(testDef());
    const SoundId tone = loadTone(rig.mixer);
    PlayDef play;
    play.gain = -1.0f;
    EXPECT_EQ(message([&] { rig.mixer.play(tone, play); }),
              "audio::Mixer::play(): gain must be >= 0, got -1");
    play.gain = 1.0f;
    play.pitch = 0.0f;
    EXPECT_EQ(message([&] { rig.mixer.play(tone, play); }),
              "audio::Mixer::play(): pitch must be in 0.01..16, got 0");
    EXPECT_EQ(message([&] { rig.mixer.play(SoundId{99}); }),
              "audio::Mixer::play(): unknown sound id 99");
    EXPECT_EQ(message([&] { rig.mixer.setMasterGain(-0.5f); }),
              "audio::Mixer::setMasterGain(): gain must be >= 0, got -0.5");
    EXPECT_EQ(message([&] { rig.mixer.stop(VoiceId{}, -1.0); }),
              "audio::Mixer::stop(): fadeOut must be >= 0 seconds, got -1");
    EXPECT_EQ(message([&] { rig.mixer.update(-0.1); }),
              "audio::Mixer::update(): dt must be >= 0 seconds, got -0.1");
    std::vector<float> odd(3);
    EXPECT_THAT(message([&] { rig.mixer.render(odd); }), HasSubstr("must be even"));
    // The component that is not finite is named with its own value (a sum would hide it).
    EXPECT_EQ(message([&] {
                  rig.mixer.setPosition(VoiceId{}, {1.0f, std::numeric_limits<float>::infinity()});
              }),
              "audio::Mixer::setPosition(): position.y must be finite, got inf");
    EXPECT_EQ(message([&] {
                  rig.mixer.setPosition(VoiceId{}, {std::nanf(""), 2.0f});
              }),
              "audio::Mixer::setPosition(): position.x must be finite, got nan");
}

// No device -------------------------------------------------------------------------------------

TEST(MixerSilent, NoDeviceRunsSilentSaysSoOnceAndEveryCallWorks) {
    MixerDef def = testDef();
    def.output = Output::Device;
    def.deviceName = "no such audio device";
    Rig rig(def);
    EXPECT_FALSE(rig.mixer.hasDevice());
    EXPECT_EQ(rig.count(core::LogLevel::Warning, "running silent"), 1);
    EXPECT_THAT(rig.messages.front().second, HasSubstr("no such audio device"));
    const SoundId tone = loadTone(rig.mixer); // 1 s
    const VoiceId voice = rig.mixer.play(tone);
    ASSERT_FALSE(voice.isNull());
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Playing);
    EXPECT_TRUE(rig.mixer.setGain(voice, 0.5f));
    EXPECT_TRUE(rig.mixer.pause(voice));
    rig.mixer.update(0.5);
    EXPECT_NEAR(rig.mixer.playbackPosition(voice), 0.0, 1e-9); // paused: stays
    EXPECT_TRUE(rig.mixer.resume(voice));
    rig.mixer.update(0.6);
    EXPECT_NEAR(rig.mixer.playbackPosition(voice), 0.6, 1e-6);
    EXPECT_TRUE(rig.mixer.stop(voice, 0.2));
    rig.mixer.update(0.1);
    EXPECT_NEAR(rig.mixer.effectiveGain(voice), 0.25f, 1e-6); // 0.5 * half the fade
    rig.mixer.update(0.1);
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Stopped);
    const VoiceId second = rig.mixer.play(tone);
    rig.mixer.update(1.01);
    EXPECT_EQ(rig.mixer.state(second), VoiceState::Stopped); // ended on time
    std::vector<float> two(2);
    EXPECT_THROW(rig.mixer.render(two), core::Error);
    EXPECT_EQ(rig.count(core::LogLevel::Warning, "running silent"), 1);
}

TEST(MixerSilent, ReopenMovesPlayingVoicesToTheDefaultDevice) {
    // ALSOFT_DRIVERS=null: the default device is OpenAL Soft's silent real-time device.
    MixerDef def = testDef();
    def.output = Output::Device;
    def.deviceName = "no such audio device";
    Rig rig(def);
    ASSERT_FALSE(rig.mixer.hasDevice());
    PlayDef play;
    play.loop = true;
    const VoiceId voice = rig.mixer.play(loadTone(rig.mixer), play);
    rig.mixer.update(0.3);
    ASSERT_TRUE(rig.mixer.reopen());
    EXPECT_TRUE(rig.mixer.hasDevice());
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Playing);
    // Where it was when the device came (the null device may have mixed a few ms since).
    EXPECT_NEAR(rig.mixer.playbackPosition(voice), 0.3, 0.1);
    rig.mixer.update(0.01);
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Playing);
}

TEST(MixerSilent, OutputNoneIsSilentOnPurpose) {
    MixerDef def = testDef();
    def.output = Output::None;
    Rig rig(def);
    EXPECT_FALSE(rig.mixer.hasDevice());
    EXPECT_EQ(rig.count(core::LogLevel::Warning, "Output::None"), 1);
    EXPECT_FALSE(rig.mixer.play(loadTone(rig.mixer)).isNull());
}

} // namespace
} // namespace e2d::audio
