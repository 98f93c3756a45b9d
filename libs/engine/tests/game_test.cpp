// SPDX-License-Identifier: MIT
// Whole games run in-process through Game::run(): a real window (Xvfb under CTest), the real
// renderer, input fed by input scripts, the mixer (silent without a device: voices still
// start and end) and the physics world. Each test is its own process under CTest.
#include <e2d/audio/mixer.hpp>
#include <e2d/core/component.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/joint_component.hpp>
#include <e2d/physics/rigidbody.hpp>
#include <e2d/physics/world.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <GLFW/glfw3.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace e2d;
using engine::Game;
using engine::GameSystem;
using testing::HasSubstr;

const std::filesystem::path kData = E2D_ENGINE_TEST_DATA;

/// This test's folder for the files it writes, engine_test_output/<test> in the test's
/// working folder (the build tree under ctest): screenshots stay there to look at, and the
/// next run of the test overwrites them.
std::filesystem::path tempDir() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::current_path() / "engine_test_output" /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return dir;
}

/// Where this test's screenshot `name` goes, with any file an earlier run left there removed,
/// so the test reads only what this run wrote.
std::filesystem::path shotPath(const std::string& name) {
    const std::filesystem::path path = tempDir() / name;
    std::filesystem::remove(path);
    return path;
}

std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    return path;
}

/// A 160 x 120 game whose first scene is `first`, plus `extra` config lines.
std::filesystem::path writeConfig(const std::string& first, const std::string& extra = {}) {
    return writeFile(tempDir() / "config.txt",
                     "firstScene = " + first +
                         "\nreferenceWindowWidth = 160\nreferenceWindowHeight = 120\n"
                         "windowWidth = 160\nwindowHeight = 120\nscreenFitMode = bestFit\n"
                         "printProfile = true\n" +
                         extra);
}

/// A scene running `setup` at initialisation and `each` every frame (update).
void addScene(Game& game, const std::string& name, std::function<void(core::Scene&)> setup,
              std::function<void(core::Scene&)> each = {}) {
    core::SceneFunctions functions{.initialize = std::move(setup)};
    if (each) {
        functions.update = [each = std::move(each)](core::Scene& scene, double) { each(scene); };
    }
    game.scenes().add(name, std::move(functions));
}

struct GameRun {
    int code = -1;
    std::vector<std::string> log;

    [[nodiscard]] int count(const std::string& text) const {
        return static_cast<int>(std::count_if(log.begin(), log.end(), [&](const std::string& line) {
            return line.find(text) != std::string::npos;
        }));
    }
    [[nodiscard]] std::string all() const {
        std::string out;
        for (const std::string& l : log) {
            out += l + "\n";
        }
        return out;
    }
};

GameRun run(Game& game, std::vector<std::string> args) {
    GameRun result;
    game.logger().setSink([&result](core::LogLevel level, std::string_view message) {
        result.log.push_back(std::string(core::toString(level)) + ": " + std::string(message));
    });
    args.insert(args.begin(), "e2d_engine_game_test");
    std::vector<char*> argv;
    for (std::string& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    result.code = game.run(static_cast<int>(args.size()), argv.data(), "no-default-config.txt");
    game.logger().setSink({});
    return result;
}

GameSystem& gameOf(const core::Scene& scene) { return scene.system<GameSystem>(); }

bool near(const std::uint8_t* p, int r, int g, int b, int tolerance) {
    return std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
           std::abs(p[2] - b) <= tolerance;
}

int countColour(const render::Image& image, int r, int g, int b, int tolerance) {
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            n += near(image.at(x, y), r, g, b, tolerance) ? 1 : 0;
        }
    }
    return n;
}

// --- Headless runs ---------------------------------------------------------------------------

TEST(Game, HeadlessRunsExactlyNFramesOfOneStepEachAndSavesTheLastFrame) {
    Game game;
    int updates = 0;
    int fixedSteps = 0;
    struct StepCounter : core::Component {
        explicit StepCounter(int& n) : count(n) {}
        void fixedUpdate(double step) override {
            EXPECT_DOUBLE_EQ(step, 1.0 / 60.0);
            ++count;
        }
        int& count;
    };
    addScene(
        game, "Red",
        [&](core::Scene& s) {
            core::GameObject& o = s.createGameObject();
            render::SpriteRendererDef def;
            def.size = {40.0f, 40.0f};
            def.tint = {255, 0, 0, 255};
            o.addComponent<render::SpriteRenderer>(def);
            o.addComponent<StepCounter>(fixedSteps);
        },
        [&](core::Scene& s) {
            EXPECT_EQ(gameOf(s).frame(), updates);
            EXPECT_TRUE(gameOf(s).headless());
            ++updates;
        });
    const std::filesystem::path shot = shotPath("shot.png");
    const GameRun r = run(game, {"--config", writeConfig("Red").string(), "--frames", "120",
                                 "--screenshot", shot.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    // 120 frames of exactly 1/60 s with a 1/60 s step: one step each, none dropped.
    EXPECT_EQ(updates, 120);
    EXPECT_EQ(fixedSteps, 120);
    EXPECT_EQ(game.profile().frames, 120);
    EXPECT_EQ(game.profile().fixedSteps, 120);
    EXPECT_EQ(game.profile().spikes, 0);
    EXPECT_EQ(game.profile().droppedSeconds, 0.0);
    EXPECT_EQ(r.count("frame profile: 120 frames, 120 fixed steps"), 1) << r.all();
    // Without a sound card (Xvfb machines), one message and the game runs silent.
    EXPECT_LE(r.count("audio::Mixer"), 1) << r.all();

    const render::Image image = render::loadImage(shot);
    ASSERT_EQ(image.width, 160);
    ASSERT_EQ(image.height, 120);
    // A 40 x 40 red square at the centre of a 160 x 120 view of a 160 x 120 reference.
    EXPECT_TRUE(near(image.at(80, 60), 255, 0, 0, 0));
    EXPECT_TRUE(near(image.at(61, 41), 255, 0, 0, 0));
    EXPECT_TRUE(near(image.at(58, 60), 0, 0, 0, 0));
    EXPECT_EQ(countColour(image, 255, 0, 0, 0), 40 * 40);
}

TEST(Game, TerminateGameEndsTheRunAndTheLastFrameIsStillSaved) {
    Game game;
    addScene(
        game, "Short",
        [](core::Scene& s) {
            render::SpriteRendererDef def;
            def.size = {20.0f, 20.0f};
            def.tint = {0, 0, 255, 255};
            s.createGameObject().addComponent<render::SpriteRenderer>(def);
        },
        [](core::Scene& s) {
            if (gameOf(s).frame() == 4) {
                gameOf(s).terminateGame();
            }
        });
    const std::filesystem::path shot = shotPath("short.png");
    const GameRun r = run(game, {"--config", writeConfig("Short").string(), "--frames", "100",
                                 "--screenshot", shot.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(game.profile().frames, 5);
    const render::Image image = render::loadImage(shot);
    EXPECT_EQ(countColour(image, 0, 0, 255, 0), 20 * 20);
}

TEST(Game, SeedMakesTheRandomNumbersReproducible) {
    const auto firstNumber = [](std::vector<std::string> extra,
                                const std::string& configExtra = {}) {
        Game game;
        std::uint64_t value = 0;
        addScene(game, "Dice", [&](core::Scene& s) { value = gameOf(s).random().next(); });
        std::vector<std::string> args{"--config", writeConfig("Dice", configExtra).string(),
                                      "--frames", "1"};
        args.insert(args.end(), extra.begin(), extra.end());
        EXPECT_EQ(run(game, args).code, 0);
        return value;
    };
    EXPECT_EQ(firstNumber({"--seed", "7"}), firstNumber({"--seed", "7"}));
    EXPECT_NE(firstNumber({"--seed", "7"}), firstNumber({"--seed", "8"}));
    // Without --seed, the config's randomSeed.
    EXPECT_EQ(firstNumber({}, "randomSeed = 7\n"), firstNumber({"--seed", "7"}));
    EXPECT_EQ(firstNumber({"--seed", "7"}), core::Random(7).next());
}

TEST(Game, AGameRunInsideARunningGameIsRefusedAndTheOuterGameKeepsWorking) {
    // GLFW is process-wide: a second Game in the same process used to initialise it again and,
    // on its way out, terminate it under the outer game (window 0x0, black frames, exit 0).
    Game outer;
    GameRun inner;
    glm::ivec2 sizeAfter{0, 0};
    addScene(
        outer, "Outer",
        [](core::Scene& s) {
            render::SpriteRendererDef def;
            def.size = {40.0f, 40.0f};
            def.tint = {0, 255, 0, 255};
            s.createGameObject().addComponent<render::SpriteRenderer>(def);
        },
        [&](core::Scene& s) {
            if (gameOf(s).frame() == 2) {
                Game nested;
                addScene(nested, "Inner", {});
                inner = run(nested, {"--config", writeConfig("Inner").string(), "--frames", "3"});
            }
            sizeAfter = gameOf(s).window().size();
        });
    const std::filesystem::path shot = shotPath("outer.png");
    const GameRun r = run(outer, {"--config", writeConfig("Outer").string(), "--frames", "6",
                                  "--screenshot", shot.string()});
    EXPECT_NE(inner.code, 0) << inner.all();
    EXPECT_EQ(inner.count("GLFW is already initialised in this process"), 1) << inner.all();
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(outer.profile().frames, 6);
    EXPECT_EQ(sizeAfter, glm::ivec2(160, 120));
    const render::Image image = render::loadImage(shot);
    EXPECT_EQ(countColour(image, 0, 255, 0, 0), 40 * 40);
}

// --- Usage, configuration and display errors --------------------------------------------------

TEST(Game, BadCommandLineExitsWith2NamingTheArgument) {
    Game game;
    addScene(game, "A", {});
    const GameRun r = run(game, {"--frames", "ten"});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.count("--frames: expected a whole number >= 1, got 'ten'"), 1) << r.all();
    EXPECT_EQ(r.count("usage:"), 1);
    EXPECT_EQ(run(game, {"--bogus"}).code, 2);
    EXPECT_EQ(run(game, {"--help"}).code, 0);
}

TEST(Game, BadConfigurationExitsWith2NamingFileLineAndKey) {
    Game game;
    addScene(game, "A", {});
    const std::filesystem::path config = writeConfig("A", "gravityY = down\nwindowWidht = 3\n");
    const GameRun r = run(game, {"--config", config.string(), "--frames", "1"});
    EXPECT_EQ(r.code, 2);
    // writeConfig puts 7 lines first: gravityY is on line 8, the misspelt key on line 9.
    EXPECT_EQ(r.count("error: " + config.string() + ":8: gravityY: expected a number, got 'down'"),
              1)
        << r.all();
    EXPECT_EQ(r.count("warning: " + config.string() + ":9: windowWidht: unknown key, ignored"), 1)
        << r.all();

    const GameRun missing = run(game, {"--config", (tempDir() / "none.txt").string()});
    EXPECT_EQ(missing.code, 2);
    EXPECT_EQ(missing.count("none.txt: cannot read the configuration file"), 1) << missing.all();

    game.scenes().add("B", core::SceneFunctions{});
    const GameRun unknown = run(game, {"--config", writeConfig("Nope").string(), "--frames", "1"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_EQ(unknown.count("firstScene: no scene is registered as 'Nope' (registered: A, B)"), 1)
        << unknown.all();

    const GameRun key =
        run(game, {"--config", writeConfig("A", "debugDrawKey = f99\n").string(), "--frames", "1"});
    EXPECT_EQ(key.code, 2);
    EXPECT_EQ(key.count("debugDrawKey: unknown key name 'f99'"), 1) << key.all();

    const GameRun bindings =
        run(game, {"--config", writeConfig("A", "bindingsFile = missing-bindings.txt\n").string(),
                   "--frames", "1"});
    EXPECT_EQ(bindings.code, 2);
    EXPECT_EQ(bindings.count("bindingsFile:"), 1) << bindings.all();
    EXPECT_EQ(bindings.count("missing-bindings.txt"), 1) << bindings.all();
}

TEST(Game, NoDisplayExitsWith3WithAClearMessage) {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    Game game;
    addScene(game, "A", {});
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "1"});
    EXPECT_EQ(r.code, 3);
    EXPECT_EQ(r.count("cannot open the game window"), 1) << r.all();
    EXPECT_EQ(r.count("set DISPLAY"), 1) << r.all();
}

// --- Scene changes release everything the old scene had ------------------------------------

TEST(Game, SceneChangeReleasesSpritesVoicesBodiesAndTextures) {
    const std::filesystem::path dir = tempDir();
    render::Image pixels;
    pixels.width = 4;
    pixels.height = 4;
    pixels.pixels.assign(4 * 4 * 4, 200);
    render::writePng(pixels, dir / "tile.png");

    struct Counts {
        int sprites = -1, voices = -1, bodies = -1, textures = -1;
    };
    const auto count = [](core::Scene& s) {
        GameSystem& g = gameOf(s);
        return Counts{g.renderer().spriteCount(), g.mixer().stats().voicesInUse,
                      g.world().bodyCount(), g.renderer().textureCount()};
    };
    Counts inA;
    Counts atB;
    Game game;
    addScene(
        game, "A",
        [&](core::Scene& s) {
            GameSystem& g = gameOf(s);
            for (int i = 0; i < 5; ++i) {
                core::GameObject& o = s.createGameObject();
                o.setPosition(glm::vec2{static_cast<float>(i) * 10.0f, 0.0f});
                render::SpriteRendererDef def;
                def.texturePath = g.asset("tile.png").string();
                o.addComponent<render::SpriteRenderer>(def);
                if (i < 4) {
                    o.addComponent<physics::Rigidbody>(physics::RigidbodyDef{});
                    o.addComponent<physics::Collider>(
                        physics::ShapeGeometry{physics::makeBox(1.0f, 1.0f)});
                }
            }
            audio::SoundData tone;
            tone.channels = 1;
            tone.sampleRate = 8000;
            tone.samples.assign(8000, 0.25f);
            const audio::SoundId sound = g.mixer().add(tone, "tone");
            for (int i = 0; i < 3; ++i) {
                audio::PlayDef play;
                play.loop = true;
                g.mixer().play(sound, play);
            }
        },
        [&](core::Scene& s) {
            if (gameOf(s).frame() == 3) {
                inA = count(s);
                gameOf(s).changeScene("B");
            }
        });
    addScene(game, "B", [&](core::Scene& s) { atB = count(s); });
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "6"});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(inA.sprites, 5);
    EXPECT_EQ(inA.voices, 3);
    EXPECT_EQ(inA.bodies, 4);
    EXPECT_EQ(inA.textures, 1);
    EXPECT_EQ(atB.sprites, 0);
    EXPECT_EQ(atB.voices, 0);
    EXPECT_EQ(atB.bodies, 0);
    EXPECT_EQ(atB.textures, 0);
    EXPECT_EQ(game.profile().sceneChanges, 1);
}

TEST(Game, MissingAssetIsReportedOnceAndThePlaceholderIsDrawn) {
    Game game;
    addScene(game, "A", [](core::Scene& s) {
        for (int i = 0; i < 3; ++i) {
            render::SpriteRendererDef def;
            def.texturePath = gameOf(s).asset("missing.png").string();
            def.size = {30.0f, 30.0f};
            core::GameObject& o = s.createGameObject();
            o.setPosition(glm::vec2{static_cast<float>(i - 1) * 40.0f, 0.0f});
            o.addComponent<render::SpriteRenderer>(def);
        }
    });
    const std::filesystem::path shot = shotPath("missing.png.shot.png");
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "10",
                                 "--screenshot", shot.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(r.count("missing.png"), 1) << r.all();
    // The magenta/black checker stands in.
    EXPECT_GT(countColour(render::loadImage(shot), 255, 0, 255, 10), 3 * 30 * 30 / 4);
}

// --- Input scripts ------------------------------------------------------------------------------

TEST(Game, InputScriptPressesActionsAndKeysOnTheirFrames) {
    struct Seen {
        std::vector<std::int64_t> jumpPressed, jumpHeld, jumpReleased, keyDown, keyUp, mouseDown;
    } seen;
    struct KeyLog : core::Component,
                    core::Handles<input::KeyDown, input::KeyUp, input::MouseButtonDown> {
        explicit KeyLog(Seen& s) : seen(s) {}
        void on(const input::KeyDown& e) override {
            if (e.key == input::Key::A) {
                seen.keyDown.push_back(scene()->system<GameSystem>().frame());
            }
        }
        void on(const input::KeyUp& e) override {
            if (e.key == input::Key::A) {
                seen.keyUp.push_back(scene()->system<GameSystem>().frame());
            }
        }
        void on(const input::MouseButtonDown& e) override {
            if (e.button == input::MouseButton::Left) {
                seen.mouseDown.push_back(scene()->system<GameSystem>().frame());
            }
        }
        Seen& seen;
    };
    Game game;
    addScene(
        game, "A", [&](core::Scene& s) { s.createGameObject().addComponent<KeyLog>(seen); },
        [&](core::Scene& s) {
            const input::ActionMap& a = gameOf(s).actions();
            const std::int64_t f = gameOf(s).frame();
            if (a.pressed("jump")) {
                seen.jumpPressed.push_back(f);
            }
            if (a.held("jump")) {
                seen.jumpHeld.push_back(f);
            }
            if (a.released("jump")) {
                seen.jumpReleased.push_back(f);
            }
        });
    const std::filesystem::path dir = tempDir();
    const std::filesystem::path script =
        writeFile(dir / "run.txt",
                  "# jump from frame 2 to 5, tap A at 7, click at 3\n2 press jump\n5 release jump\n"
                  "7 tap key:a\n3 tap fire\n");
    const std::string config =
        writeConfig("A", "bindingsFile = " + (kData / "bindings.txt").string() + "\n").string();
    const GameRun r =
        run(game, {"--config", config, "--frames", "10", "--input-script", script.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(seen.jumpPressed, (std::vector<std::int64_t>{2}));
    EXPECT_EQ(seen.jumpHeld, (std::vector<std::int64_t>{2, 3, 4}));
    EXPECT_EQ(seen.jumpReleased, (std::vector<std::int64_t>{5}));
    EXPECT_EQ(seen.keyDown, (std::vector<std::int64_t>{7}));
    EXPECT_EQ(seen.keyUp, (std::vector<std::int64_t>{8}));
    EXPECT_EQ(seen.mouseDown, (std::vector<std::int64_t>{3}));
}

TEST(Game, InputScriptErrorsNameTheLine) {
    Game game;
    addScene(game, "A", {});
    const std::filesystem::path dir = tempDir();
    const std::string config =
        writeConfig("A", "bindingsFile = " + (kData / "bindings.txt").string() + "\n").string();
    const auto errorOf = [&](const std::string& text) {
        const std::filesystem::path script = writeFile(dir / "bad.txt", text);
        const GameRun r =
            run(game, {"--config", config, "--frames", "2", "--input-script", script.string()});
        EXPECT_EQ(r.code, 2) << text;
        return r.all();
    };
    const std::string bad = (dir / "bad.txt").string();
    EXPECT_THAT(errorOf("0 press jump\n1 push jump\n"),
                HasSubstr(bad + ":2: expected press, release, tap or move, got 'push'"));
    EXPECT_THAT(
        errorOf("\n4 press dance\n"),
        HasSubstr(bad +
                  ":2: 'dance' is not an action of the game (nor a binding such as key:space)"));
    EXPECT_THAT(
        errorOf("4 press padonly\n"),
        HasSubstr(bad + ":1: action 'padonly' has no keyboard or mouse-button binding to press"));
    EXPECT_THAT(errorOf("4 press key:nokey\n"),
                HasSubstr(bad + ":1: input::parseBinding(): unknown key name"));
    EXPECT_THAT(
        errorOf("4 press axis:lefty\n"),
        HasSubstr(bad + ":1: 'axis:lefty': only key:, mouse: and button: bindings can be pressed"));
    const GameRun missing =
        run(game, {"--config", config, "--input-script", (dir / "none.txt").string()});
    EXPECT_EQ(missing.code, 2);
    EXPECT_EQ(missing.count("none.txt: cannot read the input script"), 1) << missing.all();
}

// --- Fixed steps and interpolation ---------------------------------------------------------

TEST(Game, BodiesAreDrawnBetweenTheirLastTwoStatesSoConstantSpeedLooksEven) {
    // Steps of 1/30 s, frames of 1/60 s: a step every other frame. A kinematic body moving at
    // 30 units/s jumps 1 unit per step; drawn interpolated it moves 0.5 units every frame.
    struct Sample {
        float object = 0.0f;
        float drawn = 0.0f;
    };
    std::vector<Sample> samples;
    struct Probe : core::Component, render::RenderHook {
        explicit Probe(std::vector<Sample>& s) : samples(s) {}
        void onInitialize() override { scene()->system<render::RenderSystem>().addHook(*this); }
        void onTerminate() override { scene()->system<render::RenderSystem>().removeHook(*this); }
        void beforeRender(render::Renderer& renderer) override {
            const auto* sprite = gameObject()->getComponent<render::SpriteRenderer>();
            samples.push_back(
                {gameObject()->worldPosition().x, renderer.sprite(sprite->sprite()).position.x});
        }
        std::vector<Sample>& samples;
    };
    const auto setup = [&](core::Scene& s) {
        core::GameObject& o = s.createGameObject();
        render::SpriteRendererDef sprite;
        sprite.size = {4.0f, 4.0f};
        o.addComponent<render::SpriteRenderer>(sprite);
        physics::RigidbodyDef body;
        body.type = physics::BodyType::Kinematic;
        body.linearVelocity = {30.0f, 0.0f};
        o.addComponent<physics::Rigidbody>(body);
        o.addComponent<Probe>(samples);
    };
    Game game;
    // The same scene twice: interpolation must survive the scene change (the render system
    // drops its hooks then).
    addScene(game, "A", setup, [](core::Scene& s) {
        if (gameOf(s).frame() == 19) {
            gameOf(s).changeScene("B");
        }
    });
    addScene(game, "B", setup);
    const GameRun r =
        run(game, {"--config",
                   writeConfig("A", "fixedTimestep = 0.0333333333333333\ngravityY = 0\n").string(),
                   "--frames", "40"});
    ASSERT_EQ(r.code, 0) << r.all();
    ASSERT_EQ(samples.size(), 40u);
    EXPECT_EQ(game.profile().fixedSteps, 20);
    int objectMoves = 0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        // Frames 0-19 scene A, 20-39 scene B; each starts at x = 0 and needs two steps before
        // it has two states to interpolate between.
        if (i % 20 < 4) {
            continue;
        }
        // Drawn: even half-unit steps every frame; the object itself: a whole unit every other
        // frame. Drawn one step behind the physics state, at most.
        EXPECT_NEAR(samples[i].drawn - samples[i - 1].drawn, 0.5f, 1e-3f) << i;
        const float objectStep = samples[i].object - samples[i - 1].object;
        EXPECT_TRUE(std::abs(objectStep) < 1e-4f || std::abs(objectStep - 1.0f) < 1e-3f)
            << i << " " << objectStep;
        objectMoves += objectStep > 0.5f ? 1 : 0;
        EXPECT_LE(samples[i].drawn, samples[i].object + 1e-4f);
        EXPECT_GE(samples[i].drawn, samples[i].object - 1.0f - 1e-4f);
    }
    EXPECT_EQ(objectMoves, 16);
}

// The box of pixels within `tolerance` of a colour: {minX, minY, maxX, maxY}, or all -1.
std::array<int, 4> colourBox(const render::Image& image, int r, int g, int b, int tolerance) {
    std::array<int, 4> box{-1, -1, -1, -1};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (near(image.at(x, y), r, g, b, tolerance)) {
                box = box[0] < 0 ? std::array<int, 4>{x, y, x, y}
                                 : std::array<int, 4>{std::min(box[0], x), std::min(box[1], y),
                                                      std::max(box[2], x), std::max(box[3], y)};
            }
        }
    }
    return box;
}

TEST(Game, ABodysSpriteChildLabelLineAndCameraAreDrawnFromOnePose) {
    // Headless frames are exactly one step long, so bodies are drawn a whole step behind their
    // physics state (alpha 0): 8 px at 480 units/s. Whatever is drawn for the body (its red
    // sprite, a green label on a child, a blue Drawer line at its render position, the camera
    // on a child) must come from that same pose: with the camera riding along, the picture of
    // a moving body is the picture of a body standing still, to the pixel.
    struct Line : core::Component {
        void update(double) override {
            const glm::vec2 at{gameObject()->renderPosition()};
            scene()->system<GameSystem>().renderer().drawer().line(at + glm::vec2{-30.0f, -25.0f},
                                                                   at + glm::vec2{30.0f, -25.0f},
                                                                   {0.0f, 0.0f, 1.0f, 1.0f}, 2.0f);
        }
    };
    const auto shoot = [](float speed, const std::string& name) {
        Game game;
        addScene(game, "A", [speed](core::Scene& s) {
            core::GameObject& body = s.createGameObject();
            render::SpriteRendererDef sprite;
            sprite.size = {20.0f, 20.0f};
            sprite.tint = {255, 0, 0, 255};
            body.addComponent<render::SpriteRenderer>(sprite);
            physics::RigidbodyDef def;
            def.type = physics::BodyType::Kinematic;
            def.linearVelocity = {speed, 0.0f};
            body.addComponent<physics::Rigidbody>(def);
            body.addComponent<Line>();

            core::GameObject& label = s.createGameObject();
            label.setPosition(glm::vec2{0.0f, 30.0f});
            render::TextLabelDef text;
            text.text = "HI";
            text.pixelSize = 20;
            text.color = {0, 255, 0, 255};
            label.addComponent<render::TextLabel>(text);
            body.addChild(label);

            core::GameObject& camera = s.createGameObject();
            render::CameraComponentDef view;
            view.referenceSize = {160.0f, 120.0f};
            camera.addComponent<render::CameraComponent>(view);
            body.addChild(camera);
        });
        const std::filesystem::path shot = shotPath(name);
        const GameRun r = run(game, {"--config", writeConfig("A", "gravityY = 0\n").string(),
                                     "--frames", "10", "--screenshot", shot.string()});
        EXPECT_EQ(r.code, 0) << r.all();
        return render::loadImage(shot);
    };
    const render::Image still = shoot(0.0f, "still.png");
    const render::Image moving = shoot(480.0f, "moving.png");
    const std::array<std::array<int, 3>, 3> colours{{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}};
    for (const auto& [r, g, b] : colours) {
        const std::array<int, 4> expected = colourBox(still, r, g, b, 100);
        ASSERT_GE(expected[0], 0) << r << "," << g << "," << b << " is not drawn";
        EXPECT_EQ(colourBox(moving, r, g, b, 100), expected) << r << "," << g << "," << b;
    }
    // And the body sits at the centre of the view: 20 x 20 px around (80, 60).
    EXPECT_EQ(colourBox(moving, 255, 0, 0, 0), (std::array<int, 4>{70, 50, 89, 69}));
}

TEST(Game, AFrameTimeSpikeIsClampedAndCounted) {
    Game game;
    addScene(game, "A", {}, [](core::Scene& s) {
        const std::int64_t f = gameOf(s).frame();
        if (f == 3) {
            std::this_thread::sleep_for(std::chrono::milliseconds(400));
        }
        if (f == 6) {
            gameOf(s).terminateGame();
        }
    });
    // Not headless (no --frames): real frame times.
    const GameRun r = run(
        game,
        {"--config",
         writeConfig("A", "maxFrameTime = 0.2\nmaxStepsPerFrame = 20\nvsync = false\n").string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_GE(game.profile().spikes, 1);
    // 7 frames, one of them 0.4 s counted as 0.2 s: at most 0.2 s + 6 ordinary frames of steps.
    EXPECT_EQ(game.profile().frames, 7);
    EXPECT_GE(game.profile().fixedSteps, 12); // 0.2 s at 60 Hz
    EXPECT_GT(game.profile().maxFrameMs, 350.0);
}

// --- Physics debug draw ----------------------------------------------------------------------

int debugGreenPixels(const std::vector<std::string>& extraArgs, const std::string& configExtra) {
    Game game;
    addScene(game, "A", [](core::Scene& s) {
        core::GameObject& ground = s.createGameObject();
        ground.setPosition(glm::vec2{0.0f, -20.0f});
        ground.addComponent<physics::Collider>(
            physics::ShapeGeometry{physics::makeBox(50.0f, 10.0f)});
    });
    const std::filesystem::path shot = shotPath("debug.png");
    std::vector<std::string> args{"--config",     writeConfig("A", configExtra).string(),
                                  "--frames",     "5",
                                  "--screenshot", shot.string()};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    const GameRun r = run(game, args);
    EXPECT_EQ(r.code, 0) << r.all();
    // The static shapes' outline colour (0.3, 0.9, 0.35).
    return countColour(render::loadImage(shot), 77, 230, 89, 12);
}

TEST(Game, PhysicsDebugDrawIsToggledByFlagConfigAndKey) {
    const int off = debugGreenPixels({}, "");
    EXPECT_EQ(off, 0);
    // The outline of a 100 x 20 box, 2 px wide, half of it under its AABB's 1 px red outline:
    // about 2 * (100 + 20) green pixels.
    const int flag = debugGreenPixels({"--debug-draw"}, "");
    EXPECT_GT(flag, 200);
    EXPECT_LT(flag, 300);
    EXPECT_EQ(debugGreenPixels({}, "debugDraw = true\n"), flag);
    const std::filesystem::path script = writeFile(tempDir() / "toggle.txt", "1 tap key:f1\n");
    EXPECT_EQ(debugGreenPixels({"--input-script", script.string()}, ""), flag);
    // Pressed twice: off again.
    const std::filesystem::path twice =
        writeFile(tempDir() / "twice.txt", "1 tap key:f1\n3 tap key:f1\n");
    EXPECT_EQ(debugGreenPixels({"--input-script", twice.string()}, ""), 0);
    // Another key, by config.
    const std::filesystem::path tab = writeFile(tempDir() / "tab.txt", "1 tap key:tab\n");
    EXPECT_EQ(debugGreenPixels({"--input-script", tab.string()}, "debugDrawKey = tab\n"), flag);
}

TEST(Game, PhysicsDebugDrawShowsJointsInTheirOwnColour) {
    // Two bodies without shapes, gravity off, at (-40, 20) and (40, 20) world units (1 unit is
    // 1 px, the view's centre at the origin: pixel (80 + x, 60 - y)), joined by a distance
    // joint whose anchors hang 20 units below each origin. The picture: a vertical line down
    // each side from pixel row 40 to row 60 at columns 40 and 120, a line between the anchors
    // along row 60, and a dot on each anchor.
    const auto draw = [](bool debug) {
        Game game;
        addScene(game, "A", [](core::Scene& s) {
            auto& physics = gameOf(s).physics();
            physics::RigidbodyDef still;
            still.gravityScale = 0.0f;
            core::GameObject& a = s.createGameObject();
            a.setPosition(glm::vec2{-40.0f, 20.0f});
            a.addComponent<physics::Rigidbody>(still);
            core::GameObject& b = s.createGameObject();
            b.setPosition(glm::vec2{40.0f, 20.0f});
            b.addComponent<physics::Rigidbody>(still);
            physics::DistanceJointDef rope;
            rope.localAnchorA = {0.0f, -20.0f};
            rope.localAnchorB = {0.0f, -20.0f};
            rope.length = 80.0f;
            b.addComponent<physics::JointComponent>(physics,
                                                    physics::JointComponentDef{rope, a.id()});
        });
        const std::filesystem::path shot = shotPath(debug ? "joint.png" : "joint_off.png");
        std::vector<std::string> args{
            "--config", writeConfig("A").string(), "--frames", "5", "--screenshot", shot.string()};
        if (debug) {
            args.emplace_back("--debug-draw");
        }
        const GameRun r = run(game, args);
        EXPECT_EQ(r.code, 0) << r.all();
        return render::loadImage(shot);
    };
    // The joint colour (0.1, 0.85, 0.85) reads (26, 217, 217).
    const auto joint = [](const render::Image& image, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                n += near(image.at(x, y), 26, 217, 217, 12) ? 1 : 0;
            }
        }
        return n;
    };
    const render::Image off = draw(false);
    EXPECT_EQ(joint(off, 0, 0, off.width - 1, off.height - 1), 0);
    const render::Image on = draw(true);
    ASSERT_EQ(on.width, 160);
    ASSERT_EQ(on.height, 120);
    // Each of the three lines, 2 px wide: at least one joint pixel in each row (column) it spans.
    int rowsLeft = 0;
    int rowsRight = 0;
    for (int y = 42; y <= 56; ++y) {
        rowsLeft += joint(on, 38, y, 42, y) > 0 ? 1 : 0;
        rowsRight += joint(on, 118, y, 122, y) > 0 ? 1 : 0;
    }
    EXPECT_EQ(rowsLeft, 15);
    EXPECT_EQ(rowsRight, 15);
    int columns = 0;
    for (int x = 45; x <= 115; ++x) {
        columns += joint(on, x, 58, x, 62) > 0 ? 1 : 0;
    }
    EXPECT_EQ(columns, 71);
    // The anchor dots (3 px radius) are wider than the lines.
    EXPECT_GE(joint(on, 37, 57, 43, 63), 20);
    EXPECT_GE(joint(on, 117, 57, 123, 63), 20);
    // Nothing of that colour elsewhere: the three lines' strips hold it all.
    const int all = joint(on, 0, 0, on.width - 1, on.height - 1);
    const int inStrips =
        joint(on, 36, 36, 44, 64) + joint(on, 116, 36, 124, 64) + joint(on, 45, 56, 115, 64);
    EXPECT_EQ(all, inStrips);
}

TEST(Game, InputScriptMovesTheMouseClicksAndDrivesGamepads) {
    struct Seen : core::Component,
                  core::Handles<input::MouseButtonDown, input::GamepadConnected,
                                input::GamepadButtonDown, input::GamepadButtonUp> {
        explicit Seen(std::vector<std::string>& out) : events(out) {}
        std::vector<std::string>& events;
        void on(const input::MouseButtonDown& e) override {
            events.push_back("mouse " + std::to_string(static_cast<int>(e.button)) + " at " +
                             std::to_string(static_cast<int>(e.world.x)) + "," +
                             std::to_string(static_cast<int>(e.world.y)));
        }
        void on(const input::GamepadConnected& e) override {
            events.push_back("connected " + std::to_string(e.gamepad));
        }
        void on(const input::GamepadButtonDown& e) override {
            events.push_back("down " + std::to_string(e.gamepad) + ":" +
                             std::to_string(static_cast<int>(e.button)));
        }
        void on(const input::GamepadButtonUp& e) override {
            events.push_back("up " + std::to_string(e.gamepad) + ":" +
                             std::to_string(static_cast<int>(e.button)));
        }
    };
    std::vector<std::string> seen;
    std::vector<float> leftX;
    std::vector<float> rightTrigger;
    std::vector<bool> aDown;
    Game game;
    addScene(
        game, "A", [&](core::Scene& s) { s.createGameObject().addComponent<Seen>(seen); },
        [&](core::Scene& s) {
            const input::Input& in = gameOf(s).input();
            leftX.push_back(in.gamepadAxis(0, input::GamepadAxis::LeftX));
            rightTrigger.push_back(in.gamepadAxis(1, input::GamepadAxis::RightTrigger));
            aDown.push_back(in.isGamepadButtonDown(0, input::GamepadButton::A));
        });
    const std::filesystem::path script =
        writeFile(tempDir() / "pads.txt", "1 move mouse 120 90\n"
                                          "1 tap mouse:left\n"
                                          "2 press button:a\n"
                                          "3 move axis:leftx 0.6\n"
                                          "4 move axis@1:righttrigger 1\n"
                                          "5 release button:a\n"
                                          "6 move axis:leftx 0\n");
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "8",
                                 "--input-script", script.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    // 160 x 120 window, camera at the origin: window pixel (120, 90) is world (40, -30).
    EXPECT_THAT(
        seen, testing::ElementsAre(
                  "connected 0", "connected 1", "mouse 0 at 40,-30", "down 0:0",
                  "down 1:" + std::to_string(static_cast<int>(input::GamepadButton::RightTrigger)),
                  "up 0:0"));
    ASSERT_EQ(leftX.size(), 8u);
    // The stick through its default 0.2 radial dead zone: (0.6 - 0.2) / 0.8 = 0.5.
    EXPECT_EQ(leftX[2], 0.0f);
    EXPECT_NEAR(leftX[3], 0.5f, 1e-5f);
    EXPECT_NEAR(leftX[5], 0.5f, 1e-5f);
    EXPECT_EQ(leftX[6], 0.0f);
    EXPECT_EQ(rightTrigger[3], 0.0f);
    EXPECT_NEAR(rightTrigger[4], 1.0f, 1e-5f);
    const std::vector<bool> expectA{false, false, true, true, true, false, false, false};
    EXPECT_EQ(aDown, expectA);
}

TEST(Game, InputScriptGamepadErrorsNameTheLine) {
    Game game;
    addScene(game, "A", [](core::Scene&) {});
    const auto errorOf = [&](const std::string& text) {
        const std::filesystem::path script = writeFile(tempDir() / "bad.txt", text);
        const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "1",
                                     "--input-script", script.string()});
        EXPECT_EQ(r.code, 2) << r.all();
        return r.all();
    };
    const std::string bad = (tempDir() / "bad.txt").string();
    EXPECT_THAT(errorOf("0 press axis:leftx\n"),
                HasSubstr(bad + ":1: 'axis:leftx': only key:, mouse: and button: "
                                "bindings can be pressed"));
    EXPECT_THAT(
        errorOf("0 tap key:a\n1 move key:a 1\n"),
        HasSubstr(bad + ":2: move: expected 'mouse' or a gamepad axis (axis:leftx), got 'key:a'"));
    const std::string unknown = errorOf("0 move axis:sideways 1\n");
    EXPECT_THAT(unknown, HasSubstr(bad + ":1: "));
    EXPECT_THAT(unknown, HasSubstr("'sideways'"));
    EXPECT_THAT(
        errorOf("0 move axis:lefttrigger -0.5\n"),
        HasSubstr(bad + ":1: move axis:lefttrigger: a trigger's value is in [0, 1], got -0.5"));
}

// --- Frame profile overlay ---------------------------------------------------------------------

struct OverlayRun {
    render::Image image;
    bool on = false;
};

// A 160 x 120 game drawing a mid-grey backdrop over its whole view (so the overlay's 60 % black
// backdrop shows too), run 20 frames with `extraArgs` and `configExtra`.
OverlayRun overlayRun(const std::vector<std::string>& extraArgs, const std::string& configExtra,
                      const std::string& name) {
    Game game;
    bool on = false;
    addScene(
        game, "A",
        [](core::Scene& s) {
            render::SpriteRendererDef def;
            def.size = {160.0f, 120.0f};
            def.tint = {128, 128, 128, 255};
            s.createGameObject().addComponent<render::SpriteRenderer>(def);
        },
        [&on](core::Scene& s) { on = gameOf(s).profileOverlay(); });
    const std::filesystem::path shot = shotPath(name + ".png");
    std::vector<std::string> args{"--config",     writeConfig("A", configExtra).string(),
                                  "--frames",     "20",
                                  "--screenshot", shot.string()};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    const GameRun r = run(game, args);
    EXPECT_EQ(r.code, 0) << r.all();
    return {render::loadImage(shot), on};
}

// Pixels of the overlay's colours in a region: its yellow text (255, 230, 90, antialiased, so
// any pixel clearly yellower than the grey) and its backdrop (the grey 128 darkened by 60 %
// black: 51).
struct OverlayInk {
    int text = 0;
    int backdrop = 0;
};

OverlayInk overlayInk(const render::Image& image, int x0, int y0, int x1, int y1) {
    OverlayInk ink;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const std::uint8_t* p = image.at(x, y);
            ink.text += (p[0] > p[2] + 40 && p[1] > p[2] + 30) ? 1 : 0;
            ink.backdrop += near(p, 51, 51, 51, 3) ? 1 : 0;
        }
    }
    return ink;
}

TEST(Game, ProfileOverlayIsDrawnTopLeftWhenTurnedOnByFlagConfigOrKey) {
    // Three lines of 14 px text from 6 px in, over the top 60 rows (wider than this small
    // window: it runs off its right edge).
    const OverlayRun off = overlayRun({}, "", "off");
    EXPECT_FALSE(off.on);
    const OverlayInk none = overlayInk(off.image, 0, 0, 159, 119);
    EXPECT_EQ(none.text, 0);
    EXPECT_EQ(none.backdrop, 0);

    const OverlayRun flag = overlayRun({"--profile"}, "", "flag");
    EXPECT_TRUE(flag.on);
    const OverlayInk corner = overlayInk(flag.image, 0, 0, 149, 59);
    EXPECT_GT(corner.text, 150) << "text ink in the top-left corner";
    EXPECT_GT(corner.backdrop, 1500) << "its backdrop";
    const OverlayInk rest = overlayInk(flag.image, 0, 62, 159, 119);
    EXPECT_EQ(rest.text + rest.backdrop, 0) << "nothing of it below";
    // Anchored 6 px in from the corner, the backdrop 4 px around the text: the two outermost
    // rows and columns stay grey.
    const OverlayInk top = overlayInk(flag.image, 0, 0, 159, 1);
    const OverlayInk left = overlayInk(flag.image, 0, 0, 1, 119);
    EXPECT_EQ(top.text + top.backdrop + left.text + left.backdrop, 0);
    EXPECT_EQ(overlayInk(flag.image, 2, 2, 5, 59).text, 0) << "the text starts 6 px in";

    const OverlayRun config = overlayRun({}, "showProfile = true\n", "config");
    EXPECT_TRUE(config.on);
    EXPECT_GT(overlayInk(config.image, 0, 0, 149, 59).text, 150);

    // The profileKey (default f2) turns it on; pressed again, off.
    const std::filesystem::path once = writeFile(tempDir() / "once.txt", "2 tap key:f2\n");
    const OverlayRun key = overlayRun({"--input-script", once.string()}, "", "key");
    EXPECT_TRUE(key.on);
    EXPECT_GT(overlayInk(key.image, 0, 0, 149, 59).text, 150);
    const std::filesystem::path twice =
        writeFile(tempDir() / "twice.txt", "2 tap key:f4\n5 tap key:f4\n");
    const OverlayRun keyTwice =
        overlayRun({"--input-script", twice.string()}, "profileKey = f4\n", "twice");
    EXPECT_FALSE(keyTwice.on);
    EXPECT_EQ(overlayInk(keyTwice.image, 0, 0, 159, 119).text, 0);
}

TEST(Game, ProfileOverlayStaysAfterASceneChange) {
    // The render system drops its hooks on a scene change; the engine puts its own back.
    Game game;
    addScene(
        game, "A", [](core::Scene&) {},
        [](core::Scene& s) {
            if (gameOf(s).frame() == 3) {
                gameOf(s).changeScene("B");
            }
        });
    addScene(game, "B", [](core::Scene& s) {
        render::SpriteRendererDef def;
        def.size = {160.0f, 120.0f};
        def.tint = {128, 128, 128, 255};
        s.createGameObject().addComponent<render::SpriteRenderer>(def);
    });
    const std::filesystem::path shot = shotPath("changed.png");
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "20",
                                 "--profile", "--screenshot", shot.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(game.profile().sceneChanges, 1);
    const OverlayInk ink = overlayInk(render::loadImage(shot), 0, 0, 149, 59);
    EXPECT_GT(ink.text, 150);
    EXPECT_GT(ink.backdrop, 1500);
}

TEST(Game, UnknownProfileKeyIsAConfigError) {
    Game game;
    addScene(game, "A", [](core::Scene&) {});
    const GameRun r =
        run(game, {"--config", writeConfig("A", "profileKey = f99\n").string(), "--frames", "1"});
    EXPECT_EQ(r.code, 2) << r.all();
    EXPECT_EQ(r.count("profileKey: unknown key name 'f99'"), 1) << r.all();
}

// --- Game objects: name, tag, active; mouse positions in world units ---------------------------

TEST(Game, InactiveObjectsAreNeitherUpdatedNorDrawnAndObjectsAreFoundByNameAndTag) {
    struct Counter : core::Component {
        explicit Counter(int& n) : count(n) {}
        void update(double) override { ++count; }
        int& count;
    };
    int activeUpdates = 0;
    int inactiveUpdates = 0;
    Game game;
    addScene(
        game, "A",
        [&](core::Scene& s) {
            const auto square = [&](const char* name, glm::vec2 at, render::Color colour,
                                    int& counter) {
                core::GameObject& o = s.createGameObject();
                o.setName(name);
                o.setTag("square");
                o.setPosition(at);
                render::SpriteRendererDef def;
                def.size = {20.0f, 20.0f};
                def.tint = colour;
                o.addComponent<render::SpriteRenderer>(def);
                o.addComponent<Counter>(counter);
            };
            square("green", {-40.0f, 0.0f}, {0, 255, 0, 255}, activeUpdates);
            square("blue", {40.0f, 0.0f}, {0, 0, 255, 255}, inactiveUpdates);
            EXPECT_EQ(s.findByTag("square").size(), 2u);
            s.findByName("blue")->setActive(false);
        },
        [&](core::Scene& s) { EXPECT_EQ(s.findFirstByTag("square"), s.findByName("green")); });
    const std::filesystem::path shot = shotPath("active.png");
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "5",
                                 "--screenshot", shot.string()});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_EQ(activeUpdates, 5);
    EXPECT_EQ(inactiveUpdates, 0);
    const render::Image image = render::loadImage(shot);
    EXPECT_EQ(countColour(image, 0, 255, 0, 0), 400);
    EXPECT_EQ(countColour(image, 0, 0, 255, 0), 0);
}

TEST(Game, MouseEventsCarryWorldPositionsThroughTheActiveCamera) {
    std::vector<glm::vec2> world;
    struct Mouse : core::Component, core::Handles<input::MouseMoved> {
        explicit Mouse(std::vector<glm::vec2>& w) : seen(w) {}
        void on(const input::MouseMoved& e) override { seen.push_back(e.world); }
        std::vector<glm::vec2>& seen;
    };
    Game game;
    addScene(
        game, "A",
        [&](core::Scene& s) {
            s.createGameObject().addComponent<Mouse>(world);
            gameOf(s).renderSystem().camera().setPosition({100.0f, 50.0f});
        },
        [](core::Scene& s) {
            // As GLFW's cursor callback would: window pixels from the top-left corner.
            if (gameOf(s).frame() == 1) {
                gameOf(s).input().handleCursorPos(0.0, 0.0);
            }
            if (gameOf(s).frame() == 2) {
                gameOf(s).input().handleCursorPos(120.0, 90.0);
            }
        });
    const GameRun r = run(game, {"--config", writeConfig("A").string(), "--frames", "4"});
    ASSERT_EQ(r.code, 0) << r.all();
    // 160 x 120 window showing the 160 x 120 reference around (100, 50): the top-left corner
    // is (20, 110); (120, 90) from the top-left is (40, -30) from the centre, y up.
    ASSERT_EQ(world.size(), 2u);
    EXPECT_NEAR(world[0].x, 20.0f, 1e-3f);
    EXPECT_NEAR(world[0].y, 110.0f, 1e-3f);
    EXPECT_NEAR(world[1].x, 140.0f, 1e-3f);
    EXPECT_NEAR(world[1].y, 20.0f, 1e-3f);
}

// --- What scenes reach -----------------------------------------------------------------------

TEST(Game, GameSystemGivesTheConfigAssetsAndEverySubsystem) {
    Game game;
    bool checked = false;
    const std::filesystem::path config = writeConfig("A", "unitsPerMetre = 32\nfontSize = 20\n");
    addScene(game, "A", [&](core::Scene& s) {
        GameSystem& g = gameOf(s);
        EXPECT_EQ(g.config().fontSize, 20);
        EXPECT_EQ(g.unitsPerMetre(), 32.0);
        EXPECT_EQ(g.config().file, config);
        EXPECT_EQ(g.asset("images/a.png"), config.parent_path() / "images/a.png");
        EXPECT_EQ(g.asset("/abs/b.png"), std::filesystem::path("/abs/b.png"));
        EXPECT_EQ(g.window().size(), glm::ivec2(160, 120));
        EXPECT_FALSE(g.window().visible());
        EXPECT_EQ(&g.renderer(), &g.renderSystem().renderer());
        EXPECT_NE(g.text().font(render::kDefaultFontPath, 12), nullptr);
        EXPECT_FALSE(g.input().isKeyDown(input::Key::A));
        EXPECT_EQ(g.mixer().voiceCount(), 32);
        // Gravity is m/s^2 whatever the scale.
        EXPECT_FLOAT_EQ(g.world().gravity().y, engine::EngineConfig{}.gravityY);
        EXPECT_FALSE(g.debugDraw());
        g.setDebugDraw(true);
        EXPECT_TRUE(g.debugDraw());
        checked = true;
    });
    const GameRun r = run(game, {"--config", config.string(), "--frames", "2"});
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_TRUE(checked);
}

} // namespace
