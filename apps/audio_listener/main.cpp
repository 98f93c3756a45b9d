// SPDX-License-Identifier: MIT
// Seed demo "audio 2": two sound sources (a blue one beeping, an orange one playing a tune)
// and the listener on the camera, which the arrow keys or WASD move (actions move_x, move_y).
// The circles and lines around the listener are the attenuation and panning distances; each
// source's line is labelled with what the spatial model gives it.
#include <e2d/audio/audio_listener.hpp>
#include <e2d/audio/audio_source.hpp>
#include <e2d/audio/mixer.hpp>
#include <e2d/audio/spatial.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <glm/geometric.hpp>

#include <cstdio>
#include <string>

using namespace e2d;

namespace {

constexpr float kWidth = 1024.0f;
constexpr float kHeight = 720.0f;
constexpr float kSourceRadius = 18.0f;
constexpr float kListenerSpeed = 250.0f; // world units per second

const glm::vec4 kBlue{0.2f, 0.45f, 1.0f, 1.0f};
const glm::vec4 kOrange{1.0f, 0.55f, 0.1f, 1.0f};
const glm::vec4 kGreen{0.2f, 0.9f, 0.3f, 1.0f};
const glm::vec4 kRed{1.0f, 0.25f, 0.2f, 1.0f};
const glm::vec4 kYellow{1.0f, 0.9f, 0.2f, 1.0f};
const glm::vec4 kGrey{0.6f, 0.6f, 0.6f, 1.0f};

struct Source {
    core::GameObject* object = nullptr;
    glm::vec4 colour{};
    const char* name = "";
};

class AudioListenerScene : public core::Scene {
protected:
    void onInitialize() override {
        auto& game = system<engine::GameSystem>();

        // The listener rides on the camera, so what is heard is what is in the middle.
        camera_ = &createGameObject();
        camera_->addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kWidth, kHeight}});
        camera_->addComponent<audio::AudioListener>();

        sources_[0] = {
            addSource(glm::vec2{-230.0f, 100.0f}, game.asset("assets/beeps.wav").string()), kBlue,
            "blue"};
        sources_[1] = {addSource(glm::vec2{250.0f, -90.0f}, game.asset("assets/tune.ogg").string()),
                       kOrange, "orange"};

        auto& info = createGameObject();
        info.setPosition(glm::vec3{-kWidth / 2 + 12, kHeight / 2 - 10, 10.0f});
        info_ = info.addComponent<render::TextLabel>(
            render::TextLabelDef{.pixelSize = 20, .hud = true});
    }

    void update(double dt) override {
        auto& game = system<engine::GameSystem>();
        const input::ActionMap& actions = game.actions();
        camera_->translate(glm::vec2{actions.value("move_x"), actions.value("move_y")} *
                           kListenerSpeed * static_cast<float>(dt));

        const audio::SpatialDef& spatial = game.mixer().spatial();
        const glm::vec2 listener{camera_->position()};
        render::Drawer& draw = game.renderer().drawer();
        draw.circle(listener, spatial.minAttenuationDistance, kGreen, 2.0f);
        draw.circle(listener, spatial.maxAttenuationDistance, kRed, 2.0f);
        for (float side : {-1.0f, 1.0f}) {
            const float minX = listener.x + side * spatial.minPanningDistance;
            const float maxX = listener.x + side * spatial.maxPanningDistance;
            draw.line({minX, listener.y - kHeight / 2}, {minX, listener.y + kHeight / 2 - 90},
                      kYellow, 2.0f);
            draw.line({maxX, listener.y - kHeight / 2}, {maxX, listener.y + kHeight / 2 - 90},
                      kOrange * 0.8f, 2.0f);
        }
        draw.circle(listener, 8.0f, kGrey, 2.0f);

        std::string text = "Arrows / WASD move the listener.";
        for (const Source& s : sources_) {
            const glm::vec2 at{s.object->position()};
            if (glm::distance(at, listener) > kSourceRadius) {
                draw.line(listener, at - kSourceRadius * glm::normalize(at - listener), kGrey,
                          1.0f);
            }
            draw.fillCircle(at, kSourceRadius, s.colour);
            const float gain = audio::attenuationGain(spatial, glm::distance(at, listener), 1.0f);
            const audio::StereoGains pan = audio::panGains(spatial, at.x - listener.x);
            const audio::VoiceId voice = s.object->getComponent<audio::AudioSource>()->voice();
            char line[128];
            std::snprintf(line, sizeof line,
                          "\n%s source: left %.2f, right %.2f (mixer: heard at %.2f)", s.name,
                          gain * pan.left, gain * pan.right, game.mixer().effectiveGain(voice));
            text += line;
        }
        info_->setText(text);
    }

private:
    core::GameObject* addSource(glm::vec2 at, const std::string& clip) {
        auto& object = createGameObject();
        object.setPosition(at);
        object.addComponent<audio::AudioSource>(
            audio::AudioSourceDef{.clip = clip, .loop = true, .spatial = true});
        return &object;
    }

    core::GameObject* camera_ = nullptr;
    Source sources_[2];
    render::TextLabel* info_ = nullptr;
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), AudioListenerScene);
    return game.run(argc, argv, "config.txt");
}
