// SPDX-License-Identifier: MIT
// Seed demo "audio 1": one sound source (the blue disc) that the mouse drags around a listener
// at the centre. The circles are the attenuation distances (full gain inside the green one,
// silent beyond the red one), the vertical lines the panning distances (centred between the
// yellow lines, fully left or right beyond the orange ones). The text shows what the spatial
// model gives for the source where it is.
#include <e2d/audio/audio_listener.hpp>
#include <e2d/audio/audio_source.hpp>
#include <e2d/audio/mixer.hpp>
#include <e2d/audio/spatial.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/event.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <glm/geometric.hpp>

#include <cstdio>

using namespace e2d;

namespace {

constexpr float kWidth = 1024.0f;
constexpr float kHeight = 720.0f;
constexpr float kSourceRadius = 18.0f;

const glm::vec4 kBlue{0.2f, 0.45f, 1.0f, 1.0f};
const glm::vec4 kGreen{0.2f, 0.9f, 0.3f, 1.0f};
const glm::vec4 kRed{1.0f, 0.25f, 0.2f, 1.0f};
const glm::vec4 kYellow{1.0f, 0.9f, 0.2f, 1.0f};
const glm::vec4 kOrange{1.0f, 0.55f, 0.1f, 1.0f};
const glm::vec4 kGrey{0.6f, 0.6f, 0.6f, 1.0f};

// Draws the spatial model's distances around `listener` (world units).
void drawDistances(render::Drawer& draw, const audio::SpatialDef& spatial, glm::vec2 listener) {
    draw.circle(listener, spatial.minAttenuationDistance, kGreen, 2.0f);
    draw.circle(listener, spatial.maxAttenuationDistance, kRed, 2.0f);
    const float h = kHeight;
    for (float side : {-1.0f, 1.0f}) {
        const float minX = listener.x + side * spatial.minPanningDistance;
        const float maxX = listener.x + side * spatial.maxPanningDistance;
        draw.line({minX, listener.y - h / 2}, {minX, listener.y + h / 2 - 70}, kYellow, 2.0f);
        draw.line({maxX, listener.y - h / 2}, {maxX, listener.y + h / 2 - 70}, kOrange, 2.0f);
    }
    draw.circle(listener, 8.0f, kGrey, 2.0f);
}

class AudioSpatialScene
    : public core::Scene,
      public core::Handles<input::MouseButtonDown, input::MouseButtonUp, input::MouseMoved> {
protected:
    void onInitialize() override {
        auto& game = system<engine::GameSystem>();

        // The camera carries the listener: world (0, 0) at the centre of the view.
        auto& camera = createGameObject();
        camera.addComponent<render::CameraComponent>(
            render::CameraComponentDef{.referenceSize = {kWidth, kHeight}});
        camera.addComponent<audio::AudioListener>();

        source_ = &createGameObject();
        source_->setPosition(glm::vec2{220.0f, 90.0f});
        source_->addComponent<audio::AudioSource>(audio::AudioSourceDef{
            .clip = game.asset("assets/beeps.wav").string(), .loop = true, .spatial = true});

        auto& info = createGameObject();
        info.setPosition(glm::vec3{-kWidth / 2 + 12, kHeight / 2 - 10, 10.0f});
        info_ = info.addComponent<render::TextLabel>(
            render::TextLabelDef{.pixelSize = 18, .hud = true});
    }

    void on(const input::MouseButtonDown& click) override {
        const glm::vec2 at{source_->position()};
        if (click.button == input::MouseButton::Left &&
            glm::distance(click.world, at) <= kSourceRadius * 1.5f) {
            dragging_ = true;
            grab_ = at - click.world;
        }
    }
    void on(const input::MouseButtonUp& release) override {
        if (release.button == input::MouseButton::Left)
            dragging_ = false;
    }
    void on(const input::MouseMoved& mouse) override {
        if (dragging_)
            source_->setPosition(mouse.world + grab_);
    }

    void update(double dt) override {
        static_cast<void>(dt);
        auto& game = system<engine::GameSystem>();
        const audio::SpatialDef& spatial = game.mixer().spatial();
        const glm::vec2 listener{0.0f, 0.0f};
        const glm::vec2 at{source_->position()};

        render::Drawer& draw = game.renderer().drawer();
        drawDistances(draw, spatial, listener);
        if (glm::distance(at, listener) > kSourceRadius) {
            draw.line(listener, at - kSourceRadius * glm::normalize(at - listener), kGrey, 1.0f);
        }
        draw.fillCircle(at, kSourceRadius, kBlue);

        // What the spatial model makes of it (the mixer applies the same functions).
        const float gain = audio::attenuationGain(spatial, glm::distance(at, listener), 1.0f);
        const audio::StereoGains pan = audio::panGains(spatial, at.x - listener.x);
        // And what the mixer says of the voice playing it (gain * bus * master * attenuation).
        const audio::Mixer& mixer = game.mixer();
        const audio::VoiceId voice = source_->getComponent<audio::AudioSource>()->voice();
        const bool playing = mixer.state(voice) == audio::VoiceState::Playing;
        char text[224];
        std::snprintf(text, sizeof text,
                      "Drag the blue source with the mouse.\ndistance %.0f   attenuation %.2f   "
                      "left %.2f   right %.2f\nmixer: voice %s, heard at %.2f",
                      glm::distance(at, listener), gain, gain * pan.left, gain * pan.right,
                      playing ? "playing" : "silent", mixer.effectiveGain(voice));
        info_->setText(text);
    }

private:
    core::GameObject* source_ = nullptr;
    render::TextLabel* info_ = nullptr;
    bool dragging_ = false;
    glm::vec2 grab_{0.0f, 0.0f};
};

} // namespace

int main(int argc, char** argv) {
    engine::Game game;
    E2D_REGISTER_SCENE(game.scenes(), AudioSpatialScene);
    return game.run(argc, argv, "config.txt");
}
