// SPDX-License-Identifier: MIT
// AudioSystem, AudioSource and AudioListener driving a real scene, heard through the loopback.
#include "audio_test_support.hpp"

#include <e2d/audio/audio_listener.hpp>
#include <e2d/audio/audio_source.hpp>
#include <e2d/audio/audio_system.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

namespace e2d::audio {
namespace {

using namespace test;

constexpr double kFrame = 0.01;

MixerDef loopbackDef(core::Logger& logger) {
    useNullDriver();
    MixerDef def;
    def.output = Output::Loopback;
    def.loopbackSampleRate = Rig::kRate;
    def.logger = &logger;
    def.spatial.minPanningDistance = 1.0f;
    def.spatial.maxPanningDistance = 10.0f;
    return def;
}

class AudioComponents : public ::testing::Test {
protected:
    void start(std::function<void(core::Scene&)> setup, bool withSystem = true) {
        registry.add("Test", core::SceneFunctions{.initialize = setup});
        registry.add("Empty", core::SceneFunctions{});
        if (withSystem) {
            director.addSystem(audio);
        }
        director.start("Test");
    }
    /// Runs frames of kFrame seconds (scene update, audio update, then the block is mixed) and
    /// returns the RMS of the last frame's audio.
    ChannelRms frames(int n) {
        std::vector<float> block(2 * static_cast<std::size_t>(kFrame * Rig::kRate));
        for (int i = 0; i < n; ++i) {
            director.applyPendingChange();
            director.scene()->beginFrame();
            director.scene()->dispatchUpdate(kFrame);
            audio.update(kFrame);
            audio.mixer().render(block);
        }
        return rms(block, 0, block.size() / 2);
    }

    std::vector<std::pair<core::LogLevel, std::string>> messages;
    core::Logger logger{core::LogLevel::Trace, [this](core::LogLevel level, std::string_view text) {
                            messages.emplace_back(level, std::string(text));
                        }};
    AudioSystem audio{loopbackDef(logger)};
    core::SceneRegistry registry;
    core::SceneDirector director{registry, logger};
    std::filesystem::path tone = writeSound("component_tone.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT,
                                            1, Rig::kRate, sine(1000.0, 1.0, Rig::kRate, 0.5f));
};

TEST_F(AudioComponents, SourceAndListenerFollowTheirObjects) {
    core::GameObject* ears = nullptr;
    core::GameObject* speaker = nullptr;
    AudioSource* source = nullptr;
    start([&](core::Scene& scene) {
        ears = &scene.createGameObject();
        ears->addComponent<AudioListener>();
        speaker = &scene.createGameObject();
        speaker->setPosition(glm::vec2(20.0f, 0.0f));
        AudioSourceDef def;
        def.clip = tone.string();
        def.loop = true;
        def.spatial = true;
        def.attenuationFactor = 0.0f;
        source = speaker->addComponent<AudioSource>(def);
    });
    ChannelRms r = frames(5);
    ASSERT_TRUE(source->isPlaying());
    EXPECT_LT(r.left, 1e-4);
    EXPECT_NEAR(r.right, sineRms(0.5), 0.01);

    speaker->setPosition(glm::vec2(-20.0f, 3.0f));
    r = frames(2);
    EXPECT_NEAR(r.left, sineRms(0.5), 0.01);
    EXPECT_LT(r.right, 1e-4);

    // The listener moves next to the speaker: centred.
    ears->setPosition(glm::vec2(-20.5f, 0.0f));
    r = frames(2);
    EXPECT_NEAR(r.left, r.right, 1e-4);
    EXPECT_NEAR(r.left, sineRms(0.5) * std::cos(std::numbers::pi / 4), 0.01);
    EXPECT_EQ(audio.mixer().listenerPosition(), glm::vec2(-20.5f, 0.0f));
}

TEST_F(AudioComponents, SourceOnAChildFollowsTheWorldPosition) {
    core::GameObject* parent = nullptr;
    start([&](core::Scene& scene) {
        scene.createGameObject().addComponent<AudioListener>();
        parent = &scene.createGameObject();
        parent->setPosition(glm::vec2(-30.0f, 0.0f));
        core::GameObject& child = scene.createGameObject();
        child.setParent(parent);
        child.setPosition(glm::vec2(60.0f, 0.0f)); // world x = 30: right
        AudioSourceDef def;
        def.clip = tone.string();
        def.loop = true;
        def.spatial = true;
        def.attenuationFactor = 0.0f;
        child.addComponent<AudioSource>(def);
    });
    ChannelRms r = frames(3);
    EXPECT_LT(r.left, 1e-4);
    parent->setPosition(glm::vec2(-90.0f, 0.0f)); // world x = -30: left
    r = frames(2);
    EXPECT_LT(r.right, 1e-4);
}

TEST_F(AudioComponents, ASecondListenerWarnsOnceAndStaysInactive) {
    AudioListener* first = nullptr;
    AudioListener* second = nullptr;
    core::GameObject* secondObject = nullptr;
    start([&](core::Scene& scene) {
        first = scene.createGameObject().addComponent<AudioListener>();
        secondObject = &scene.createGameObject();
        secondObject->setPosition(glm::vec2(100.0f, 100.0f));
        second = secondObject->addComponent<AudioListener>();
    });
    frames(3);
    EXPECT_TRUE(first->isActive());
    EXPECT_FALSE(second->isActive());
    EXPECT_EQ(audio.activeListener(), first);
    EXPECT_EQ(audio.mixer().listenerPosition(), glm::vec2(0.0f, 0.0f));
    secondObject->setPosition(glm::vec2(5.0f, 5.0f));
    frames(3);
    EXPECT_EQ(audio.mixer().listenerPosition(), glm::vec2(0.0f, 0.0f));
    int warnings = 0;
    for (const auto& [level, text] : messages) {
        warnings +=
            level == core::LogLevel::Warning && text.find("another listener") != std::string::npos
                ? 1
                : 0;
    }
    EXPECT_EQ(warnings, 1);
}

TEST_F(AudioComponents, FadesPauseAndResumeThroughTheComponent) {
    AudioSource* source = nullptr;
    start([&](core::Scene& scene) {
        AudioSourceDef def;
        def.clip = tone.string();
        def.loop = true;
        def.fadeIn = 0.2;
        def.fadeOut = 0.3;
        source = scene.createGameObject().addComponent<AudioSource>(def);
    });
    frames(1);
    const ChannelRms early = frames(9); // 0.1 s into a 0.2 s fade-in
    const ChannelRms full = frames(20);
    EXPECT_NEAR(early.left / full.left, 0.5, 0.06);
    source->pause();
    frames(31);
    EXPECT_TRUE(source->isPaused());
    EXPECT_LT(frames(1).left, 1e-6);
    source->resume(0.0);
    EXPECT_NEAR(frames(2).left / full.left, 1.0, 0.01);
    source->stop(0.0);
    frames(1);
    EXPECT_FALSE(source->isPlaying());
    EXPECT_TRUE(source->voice().isNull());
    EXPECT_LT(frames(1).left, 1e-6);
    EXPECT_TRUE(source->play());
    EXPECT_TRUE(source->isPlaying());
}

TEST_F(AudioComponents, SceneChangeStopsEveryVoice) {
    start([&](core::Scene& scene) {
        AudioSourceDef def;
        def.clip = tone.string();
        def.loop = true;
        scene.createGameObject().addComponent<AudioSource>(def);
    });
    EXPECT_GT(frames(3).left, 0.1);
    EXPECT_EQ(audio.mixer().stats().voicesInUse, 1);
    director.changeToScene("Empty");
    EXPECT_LT(frames(2).left, 1e-6);
    EXPECT_EQ(audio.mixer().stats().voicesInUse, 0);
}

TEST_F(AudioComponents, WithoutAnAudioSystemTheErrorNamesIt) {
    try {
        start([&](core::Scene& scene) { scene.createGameObject().addComponent<AudioListener>(); },
              false);
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("AudioSystem"));
    }
}

TEST_F(AudioComponents, InvalidDefNamesTheField) {
    AudioSourceDef def;
    def.pitch = 40.0f;
    try {
        AudioSource source(def);
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "audio::AudioSource::AudioSource(): pitch must be in 0.01..16, got 40");
    }
}

} // namespace
} // namespace e2d::audio
