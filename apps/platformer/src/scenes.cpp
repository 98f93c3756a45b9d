// SPDX-License-Identifier: MIT
#include "scenes.hpp"

#include "level.hpp"

#include <e2d/audio/mixer.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/render/animation.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>
#include <e2d/render/text_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace platformer {

namespace render = e2d::render;
namespace audio = e2d::audio;
using e2d::core::GameObject;
using e2d::engine::GameSystem;

namespace {

constexpr glm::vec2 kReference{1280.0f, 720.0f};
// Seconds the level keeps showing after the player won or died, before the next scene.
constexpr double kOutroTime = 1.0;

// Depth order (SpriteRenderer's object z).
constexpr float kZSky = -10.0f;
constexpr float kZHills = -9.0f;
constexpr float kZTrees = -8.0f;
constexpr float kZGround = 0.0f;
constexpr float kZProps = 1.0f;
constexpr float kZPlayer = 2.0f;

GameObject& makeSprite(e2d::core::Scene& scene, const render::SpriteRendererDef& def,
                       glm::vec2 position, float z) {
    GameObject& object = scene.createGameObject();
    object.setPosition(glm::vec3(position, z));
    object.addComponent<render::SpriteRenderer>(def);
    return object;
}

render::SpriteRendererDef textured(const GameSystem& game, std::string_view file, glm::vec2 size) {
    render::SpriteRendererDef def;
    def.texturePath = game.asset(std::string("assets/") + std::string(file)).string();
    def.size = size;
    return def;
}

render::SpriteRendererDef tinted(render::TextureId white, glm::vec2 size, render::Color tint) {
    render::SpriteRendererDef def;
    def.texture = white;
    def.size = size;
    def.tint = tint;
    return def;
}

// The sky, far hills and near trees. On the menus they are HUD sprites (fixed on screen). In
// the level the sky stays put (parallax 0) and the others scroll slower than the level
// (parallax 0.25 and 0.55). A parallax sprite appears at `camera + k * (position - camera)`
// while its size stays the same, so copies that touch on screen are W / k apart in the world,
// and a layer sits `offset / k` below the camera height it is designed for; a block of the
// layer's bottom colour under it keeps the screen covered when the camera climbs.
void addBackground(e2d::core::Scene& scene, const GameSystem& game, render::TextureId white,
                   std::optional<float> designCameraY) {
    render::SpriteRendererDef sky = textured(game, "sky.png", kReference);
    sky.parallax = 0.0f;
    sky.hud = !designCameraY;
    makeSprite(scene, sky, {0.0f, 0.0f}, kZSky);
    struct Layer {
        const char* file;
        float parallax;
        float z;
        float offset; // layer centre below the view's centre, reference pixels
        render::Color bottom;
    };
    const glm::vec2 size{1280.0f, 360.0f};
    for (const Layer& layer : {Layer{"hills.png", 0.25f, kZHills, -120.0f, {120, 170, 200, 255}},
                               Layer{"trees.png", 0.55f, kZTrees, -200.0f, {60, 130, 90, 255}}}) {
        render::SpriteRendererDef def = textured(game, layer.file, size);
        if (!designCameraY) {
            def.hud = true;
            makeSprite(scene, def, {0.0f, layer.offset}, layer.z);
            continue;
        }
        const float k = layer.parallax;
        def.parallax = k;
        render::SpriteRendererDef below = tinted(white, {size.x, 720.0f}, layer.bottom);
        below.parallax = k;
        const float y = *designCameraY + layer.offset / k;
        for (int i = -1; i <= 2; ++i) {
            const float x = static_cast<float>(i) * size.x / k;
            makeSprite(scene, def, {x, y}, layer.z);
            makeSprite(scene, below, {x, y - (0.5f * size.y + 360.0f) / k}, layer.z);
        }
    }
}

// Draws one line of HUD text (camera space: origin at the view's centre).
void hudText(GameSystem& game, std::string_view text, glm::vec2 at, int size,
             render::HorizontalAlign horizontal, render::Color color = {}) {
    render::Font* font = game.text().font(render::kDefaultFontPath, size);
    if (font == nullptr) {
        return;
    }
    render::TextStyle style;
    style.horizontal = horizontal;
    style.vertical = render::VerticalAlign::Center;
    render::TextDraw where;
    where.hud = true;
    // A dark shadow a little down and right keeps light text readable over the sky.
    where.position = at + glm::vec2(0.06f, -0.06f) * static_cast<float>(size);
    where.z = 49.0f;
    where.color = {20, 30, 60, 160};
    game.text().draw(*font, text, style, where);
    where.position = at;
    where.z = 50.0f;
    where.color = color;
    game.text().draw(*font, text, style, where);
}

// The engine loads the config's bindingsFile (bindings.txt) into the game's actions; when an
// action is missing from it (no file, or a file without it), these bindings stand in.
void ensureBindings(GameSystem& game) {
    e2d::input::ActionMap& actions = game.actions();
    const char* defaults[][2] = {{"move", "move = keys:left/right, keys:a/d, axis:leftx"},
                                 {"jump", "jump = key:space, key:up, key:w, button:a"},
                                 {"start", "start = key:enter, key:space, button:start, button:a"},
                                 {"quit", "quit = key:escape, button:back"},
                                 {"checkpoint", "checkpoint = key:f5"},
                                 {"restore", "restore = key:f9"}};
    for (const auto& [name, line] : defaults) {
        if (actions.find(name).isNull()) {
            actions.loadFromString(line, "<platformer defaults>");
        }
    }
}

// A title-like scene: background, a heading, lines of text, and the action that moves on.
class MenuScene : public e2d::core::Scene {
protected:
    MenuScene(Session& session, std::string heading, render::Color headingColor)
        : session_(session), heading_(std::move(heading)), headingColor_(headingColor) {}

    void onInitialize() override {
        GameSystem& game = system<GameSystem>();
        ensureBindings(game);
        GameObject& camera = createGameObject();
        render::CameraComponentDef cameraDef;
        cameraDef.referenceSize = kReference;
        camera.addComponent<render::CameraComponent>(cameraDef);
        addBackground(*this, game, game.renderer().whiteTexture(), std::nullopt);
        session_.lastScene = name();
    }

    void update(double dt) override {
        static_cast<void>(dt);
        GameSystem& game = system<GameSystem>();
        hudText(game, heading_, {0.0f, 140.0f}, 72, render::HorizontalAlign::Center, headingColor_);
        float y = 30.0f;
        for (const std::string& line : lines()) {
            hudText(game, line, {0.0f, y}, 32, render::HorizontalAlign::Center);
            y -= 48.0f;
        }
        if (game.actions().pressed("start")) {
            game.changeScene("LevelScene");
        } else if (game.actions().pressed("quit")) {
            game.terminateGame();
        }
    }

    [[nodiscard]] virtual std::vector<std::string> lines() const = 0;

    Session& session_;

private:
    std::string heading_;
    render::Color headingColor_;
};

class TitleScene final : public MenuScene {
public:
    explicit TitleScene(Session& session)
        : MenuScene(session, "e2d platformer", {255, 230, 90, 255}) {}

private:
    [[nodiscard]] std::vector<std::string> lines() const override {
        return {"Collect the coins, ride the lift, reach the flag.",
                "Arrows or A/D to run, Space to jump (gamepad: stick and A).",
                "Press Enter or Start to play, Escape to quit."};
    }
};

class GameOverScene final : public MenuScene {
public:
    explicit GameOverScene(Session& session)
        : MenuScene(session, "Game over", {255, 90, 80, 255}) {}

private:
    [[nodiscard]] std::vector<std::string> lines() const override {
        return {"Coins: " + std::to_string(session_.score) + " of " +
                    std::to_string(session_.coinCount),
                "Press Enter or Start to try again."};
    }
};

class WinScene final : public MenuScene {
public:
    explicit WinScene(Session& session) : MenuScene(session, "You win!", {120, 240, 120, 255}) {}

private:
    [[nodiscard]] std::vector<std::string> lines() const override {
        std::ostringstream time;
        time.precision(1);
        time << std::fixed << session_.levelTime;
        return {"Coins: " + std::to_string(session_.score) + " of " +
                    std::to_string(session_.coinCount) + "   Time: " + time.str() + " s",
                "Press Enter or Start to play again."};
    }
};

// The level: the rules (Level) as game objects on the engine's physics components, drawn with
// sprites on those objects, heard through the mixer, driven by input actions.
class LevelScene final : public e2d::core::Scene {
public:
    explicit LevelScene(Session& session) : session_(session) {}

private:
    void onInitialize() override {
        GameSystem& game = system<GameSystem>();
        ensureBindings(game);
        level_ = std::make_unique<Level>(*this);
        session_.levelBodies = 0; // counted once the level's objects joined the scene
        session_.lastScene = name();
        session_.runs += 1;
        session_.score = 0;
        session_.coinCount = level_->coinCount();
        session_.jumps = 0;

        GameObject& camera = createGameObject();
        render::CameraComponentDef cameraDef;
        cameraDef.referenceSize = kReference;
        camera.addComponent<render::CameraComponent>(cameraDef);
        camera_ = &camera;

        // Designed for the camera's height at the start (player on the ground).
        addBackground(*this, game, game.renderer().whiteTexture(), 2.1f * kTile);
        buildTerrain(game);
        buildProps(game);
        buildPlayer(game);
        loadSounds(game);
        followPlayer(1.0);
    }

    void buildTerrain(GameSystem& game) {
        const render::TextureId white = game.renderer().whiteTexture();
        const std::vector<glm::vec2>& t = level_->terrain();
        constexpr float kBottom = -14.0f * kTile;
        // Floors (horizontal runs of the chain, listed right to left): earth below, grass on top.
        for (std::size_t i = 0; i + 1 < t.size(); ++i) {
            const glm::vec2 a = t[i];
            const glm::vec2 b = t[i + 1];
            if (a.y != b.y) {
                continue;
            }
            const glm::vec2 size{a.x - b.x, a.y - kBottom};
            makeSprite(*this, tinted(white, size, {110, 72, 44, 255}),
                       {(a.x + b.x) * 0.5f, (a.y + kBottom) * 0.5f}, kZGround);
            for (float x = b.x; x < a.x - 0.01f * kTile; x += kTile) {
                makeSprite(*this, textured(game, "grass.png", glm::vec2{1.0f, 0.5f} * kTile),
                           {x + 0.5f * kTile, a.y - 0.25f * kTile}, kZGround + 0.1f);
            }
        }
        // The end walls (first and last segments of the chain).
        for (glm::vec2 top : {t.front(), t.back()}) {
            const float outward = top.x > 0.0f ? 1.0f : -1.0f;
            makeSprite(*this, tinted(white, {2.0f * kTile, top.y - kBottom}, {92, 60, 38, 255}),
                       {top.x + outward * kTile, (top.y + kBottom) * 0.5f}, kZGround);
        }
    }

    void buildProps(GameSystem& game) {
        for (const Box& hazard : level_->hazards()) {
            for (float x = hazard.center.x - hazard.half.x;
                 x < hazard.center.x + hazard.half.x - 0.01f * kTile; x += kTile) {
                makeSprite(*this, textured(game, "spikes.png", {kTile, 2.0f * hazard.half.y}),
                           {x + 0.5f * kTile, hazard.center.y}, kZProps);
            }
        }
        const Box& oneWay = level_->oneWay();
        for (float x = oneWay.center.x - oneWay.half.x;
             x < oneWay.center.x + oneWay.half.x - 0.01f * kTile; x += kTile) {
            makeSprite(*this, textured(game, "plank.png", glm::vec2{1.0f, 0.3f} * kTile),
                       {x + 0.5f * kTile, oneWay.center.y + oneWay.half.y - 0.15f * kTile},
                       kZProps);
        }
        // The platforms' and coins' sprites go on their objects, and move with them.
        for (const MovingPlatform& platform : level_->platforms()) {
            platform.object->setPosition(
                glm::vec3(platform.object->position().x, platform.object->position().y, kZProps));
            platform.object->addComponent<render::SpriteRenderer>(
                textured(game, "platform.png", 2.0f * platform.half));
        }
        for (const Coin& coin : level_->coins()) {
            // On a child, which bobs and spins while the coin's sensor stays put.
            GameObject& sprite = createGameObject();
            coin.object->addChild(sprite);
            sprite.setPosition(glm::vec3(0.0f, 0.0f, kZProps));
            sprite.addComponent<render::SpriteRenderer>(
                textured(game, "coin.png", glm::vec2{0.7f, 0.7f} * kTile));
            coins_.push_back(&sprite);
        }
        const Box& goal = level_->goal();
        makeSprite(*this, textured(game, "flag.png", 2.0f * goal.half), goal.center, kZProps);
    }

    void buildPlayer(GameSystem& game) {
        render::SpriteRendererDef def;
        def.size = 2.0f * Level::playerHalfSize() * glm::vec2(1.4f, 1.1f);
        def.pivot = {0.5f, 0.45f};
        try {
            sheet_ = render::SpriteSheet::fromFile(game.asset("assets/player.json"));
            def.texturePath = sheet_->imagePath().string();
            for (const char* name : {"idle", "run", "jump", "fall"}) {
                frames_.push_back(sheet_->animationFrames(name));
            }
        } catch (const e2d::core::Error& error) {
            // No sheet: the player is a plain box, the game goes on.
            if (logger() != nullptr) {
                logger()->warning(error.what());
            }
            sheet_.reset();
            def.texture = game.renderer().whiteTexture();
            def.tint = {240, 120, 60, 255};
        }
        player_ = &level_->player();
        player_->setPosition(glm::vec3(level_->playerPosition(), kZPlayer));
        player_->addComponent<render::SpriteRenderer>(def);
        setPose(Pose::Idle);
    }

    void loadSounds(GameSystem& game) {
        audio::Mixer& mixer = game.mixer();
        coinSound_ = mixer.load(game.asset("assets/coin.wav"));
        jumpSound_ = mixer.load(game.asset("assets/jump.wav"));
        hurtSound_ = mixer.load(game.asset("assets/hurt.wav"));
        winSound_ = mixer.load(game.asset("assets/win.wav"));
        const audio::SoundId music =
            mixer.load(game.asset("assets/music.ogg"), audio::LoadMode::Stream);
        audio::PlayDef def;
        def.loop = true;
        def.gain = 0.5f;
        def.bus = audio::Bus::Music;
        def.fadeIn = 1.0;
        music_ = mixer.play(music, def);
        session_.musicStreaming =
            mixer.isValid(music_) && mixer.soundInfo(music).mode == audio::LoadMode::Stream;
    }

    enum class Pose { Idle, Run, Jump, Fall };

    void setPose(Pose pose) {
        if (pose == pose_ && animation_) {
            return;
        }
        pose_ = pose;
        const std::span<const int> frames = framesOf(pose);
        render::AnimationDef def;
        def.frameCount = std::max<int>(1, static_cast<int>(frames.size()));
        def.frameDuration = pose == Pose::Run ? 0.08 : 0.2;
        animation_.emplace(def);
    }

    [[nodiscard]] std::span<const int> framesOf(Pose pose) const {
        const auto index = static_cast<std::size_t>(pose);
        return index < frames_.size() ? std::span<const int>(frames_[index])
                                      : std::span<const int>();
    }

    void update(double dt) override {
        GameSystem& game = system<GameSystem>();
        const e2d::input::ActionMap& actions = game.actions();
        jumpLatch_ = jumpLatch_ || actions.pressed("jump");
        if (actions.pressed("quit")) {
            game.changeScene("TitleScene");
        }
        // F5 keeps the run as it is now (the level's rules and the scene's physics), F9 goes
        // back to it.
        if (actions.pressed("checkpoint")) {
            checkpoint_ = level_->save();
        } else if (actions.pressed("restore") && checkpoint_) {
            level_->restore(*checkpoint_);
        }
        if (level_->won() || level_->dead()) {
            outro_ += dt;
            if (outro_ >= kOutroTime && !leaving_) {
                leaving_ = true;
                game.changeScene(level_->won() ? "WinScene" : "GameOverScene");
            }
        }
        animatePlayer(dt);
        for (std::size_t i = 0; i < coins_.size(); ++i) {
            const Coin& coin = level_->coins()[i];
            auto* sprite = coins_[i]->getComponent<render::SpriteRenderer>();
            sprite->setVisible(!coin.collected);
            // A gentle bob and a spin (scaling x) so coins catch the eye.
            const double phase = level_->time() * 3.0 + static_cast<double>(i);
            coins_[i]->setPosition(
                glm::vec3(0.0f, 0.08f * kTile * static_cast<float>(std::sin(phase)), kZProps));
            coins_[i]->setScale(
                {static_cast<float>(std::abs(std::cos(phase * 0.7))) * 0.8f + 0.2f, 1.0f});
        }
        followPlayer(dt);
        hudText(game,
                "Coins " + std::to_string(level_->score()) + " / " +
                    std::to_string(level_->coinCount()),
                {-620.0f, 330.0f}, 32, render::HorizontalAlign::Left, {255, 230, 90, 255});
        if (level_->won()) {
            hudText(game, "Goal!", {0.0f, 120.0f}, 72, render::HorizontalAlign::Center,
                    {120, 240, 120, 255});
        } else if (level_->dead()) {
            hudText(game, "Ouch!", {0.0f, 120.0f}, 72, render::HorizontalAlign::Center,
                    {255, 90, 80, 255});
        }
    }

    void fixedUpdate(double step) override {
        GameSystem& game = system<GameSystem>();
        const e2d::input::ActionMap& actions = game.actions();
        PlayerInput input;
        input.move = actions.value("move");
        input.jumpHeld = actions.held("jump");
        input.jumpPressed = jumpLatch_;
        jumpLatch_ = false;
        if (session_.levelBodies == 0) {
            // The level's objects joined the scene at the start of this frame.
            session_.levelBodies = game.world().bodyCount();
        }
        const bool wasOver = level_->won() || level_->dead();
        level_->fixedUpdate(input, static_cast<float>(step));
        const StepEvents& events = level_->events();
        audio::Mixer& mixer = game.mixer();
        for (int i = 0; i < events.coinsCollected; ++i) {
            const audio::VoiceId voice = mixer.play(coinSound_);
            if (mixer.isValid(voice)) {
                session_.coinVoices += 1;
            }
        }
        if (events.jumped) {
            audio::PlayDef def;
            def.gain = 0.6f;
            mixer.play(jumpSound_, def);
        }
        if (!wasOver && (events.won || events.died)) {
            mixer.play(events.won ? winSound_ : hurtSound_);
            mixer.stop(music_, 0.5);
            if (events.won) {
                session_.wins += 1;
            } else {
                session_.deaths += 1;
            }
        }
        session_.score = level_->score();
        session_.jumps = level_->jumps();
        session_.levelTime = level_->time();
        session_.stepsOnMovingPlatform = level_->stepsOnMovingPlatform();
        session_.stepsOnOneWay = level_->stepsOnOneWay();
    }

    void animatePlayer(double dt) {
        const glm::vec2 v = level_->playerVelocity();
        Pose pose = Pose::Idle;
        if (!level_->grounded()) {
            pose = v.y > 0.0f ? Pose::Jump : Pose::Fall;
        } else if (std::abs(v.x) > 0.5f * kTile) {
            pose = Pose::Run;
        }
        setPose(pose);
        animation_->update(dt);
        auto* sprite = player_->getComponent<render::SpriteRenderer>();
        sprite->setFlip(level_->facing() < 0, false);
        const std::span<const int> frames = framesOf(pose_);
        if (sheet_ && !frames.empty()) {
            const int frame = frames[static_cast<std::size_t>(animation_->frame()) % frames.size()];
            sprite->setUv(sheet_->frames()[static_cast<std::size_t>(frame)].uv);
        }
    }

    void followPlayer(double dt) {
        // The camera eases towards a point a little ahead of the player, kept inside the level.
        const glm::vec2 target = level_->playerPosition() + glm::vec2(3.0f, 1.5f) * kTile;
        glm::vec2 at = glm::vec2(camera_->position());
        const float k = 1.0f - static_cast<float>(std::exp(-6.0 * dt));
        at += (target - at) * k;
        const float halfWidth = kReference.x * 0.5f;
        at.x =
            std::clamp(at.x, -4.0f * kTile + halfWidth - 96.0f, 36.0f * kTile - halfWidth + 96.0f);
        at.y = std::max(at.y, -3.5f * kTile + kReference.y * 0.5f - 200.0f);
        camera_->setPosition(at);
    }

    Session& session_;
    std::unique_ptr<Level> level_;
    GameObject* camera_ = nullptr;
    GameObject* player_ = nullptr;
    std::vector<GameObject*> coins_; // the coins' sprites
    std::optional<render::SpriteSheet> sheet_;
    std::vector<std::vector<int>> frames_;
    std::optional<render::Animation> animation_;
    Pose pose_ = Pose::Idle;
    audio::SoundId coinSound_{};
    audio::SoundId jumpSound_{};
    audio::SoundId hurtSound_{};
    audio::SoundId winSound_{};
    audio::VoiceId music_{};
    bool jumpLatch_ = false;
    std::optional<LevelCheckpoint> checkpoint_;
    double outro_ = 0.0;
    bool leaving_ = false;
};

} // namespace

std::string stateLine(const Session& s) {
    std::ostringstream out;
    out << "platformer: scene=" << s.lastScene << " score=" << s.score << '/' << s.coinCount
        << " coin_voices=" << s.coinVoices << " jumps=" << s.jumps << " runs=" << s.runs
        << " deaths=" << s.deaths << " wins=" << s.wins
        << " steps_on_moving_platform=" << s.stepsOnMovingPlatform
        << " steps_on_one_way=" << s.stepsOnOneWay
        << " music_streaming=" << (s.musicStreaming ? 1 : 0) << " level_bodies=" << s.levelBodies;
    out.precision(2);
    out << std::fixed << " level_time=" << s.levelTime;
    return out.str();
}

void registerScenes(e2d::core::SceneRegistry& registry, Session& session) {
    registry.add("TitleScene", [&session] { return std::make_unique<TitleScene>(session); });
    registry.add("LevelScene", [&session] { return std::make_unique<LevelScene>(session); });
    registry.add("GameOverScene", [&session] { return std::make_unique<GameOverScene>(session); });
    registry.add("WinScene", [&session] { return std::make_unique<WinScene>(session); });
}

} // namespace platformer
