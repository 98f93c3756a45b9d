// SPDX-License-Identifier: MIT
// The engine's configuration: every key read from a file, the physics keys reaching the world,
// and the malformed cases (bad values name file, line and key; unknown keys are warnings).
#include <e2d/engine/engine_config.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace e2d;
using engine::EngineConfigResult;
using engine::loadEngineConfig;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;

const std::filesystem::path kData = E2D_ENGINE_TEST_DATA;

// The diagnostics of one severity as text, in order.
std::vector<std::string> texts(const EngineConfigResult& r, core::Severity severity) {
    std::vector<std::string> out;
    for (const core::Diagnostic& d : r.diagnostics.only(severity)) {
        out.push_back(d.toString());
    }
    return out;
}
std::vector<std::string> errors(const EngineConfigResult& r) {
    return texts(r, core::Severity::Error);
}
std::vector<std::string> warnings(const EngineConfigResult& r) {
    return texts(r, core::Severity::Warning);
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "e2d_engine_config_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    return path;
}

TEST(EngineConfig, EveryKeyOfTheFileIsRead) {
    const EngineConfigResult r = loadEngineConfig(kData / "every_key.txt", true);
    EXPECT_THAT(errors(r), IsEmpty());
    EXPECT_THAT(warnings(r), IsEmpty());
    const engine::EngineConfig& c = r.config;
    EXPECT_EQ(c.file, kData / "every_key.txt");
    EXPECT_EQ(c.assetRoot, kData);
    EXPECT_EQ(c.firstScene, "Level");
    EXPECT_EQ(c.referenceWindowWidth, 800);
    EXPECT_EQ(c.referenceWindowHeight, 600);
    EXPECT_EQ(c.windowWidth, 400);
    EXPECT_EQ(c.windowHeight, 300);
    EXPECT_EQ(c.screenFitMode, render::ScreenFit::HeightFit);
    EXPECT_EQ(c.windowMode, render::WindowMode::Fullscreen);
    EXPECT_EQ(c.windowTitle, "every key test");
    EXPECT_EQ(c.textureFilteringMode, render::TextureFilter::Linear);
    EXPECT_EQ(c.maxCameraDepth, 500.0f);
    EXPECT_FALSE(c.vsync);
    EXPECT_EQ(c.msaaSamples, 4);
    EXPECT_EQ(c.fontSize, 32);
    EXPECT_EQ(c.gravityX, 0.5f);
    EXPECT_EQ(c.gravityY, -10.0f);
    EXPECT_EQ(c.fixedTimestep, 0.005);
    EXPECT_EQ(c.collisionResolutionSteps, 10);
    EXPECT_EQ(c.physicsSolver, physics::SolverMode::Classic);
    EXPECT_EQ(c.allowedPenetration, 0.001f);
    EXPECT_EQ(c.penetrationBiasFactor, 0.1f);
    EXPECT_EQ(c.minRigidbodySpeed, 0.05f);
    EXPECT_EQ(c.physicsWorkers, 2);
    EXPECT_EQ(c.unitsPerMetre, 100.0);
    EXPECT_EQ(c.minAttenuationDistance, 100.0f);
    EXPECT_EQ(c.maxAttenuationDistance, 900.0f);
    EXPECT_EQ(c.minPanningDistance, 50.0f);
    EXPECT_EQ(c.maxPanningDistance, 700.0f);
    EXPECT_EQ(c.masterGain, 0.5f);
    EXPECT_EQ(c.voiceCount, 48);
    EXPECT_EQ(c.bindingsFile, "bindings.txt");
    EXPECT_FALSE(c.keyRepeat);
    EXPECT_EQ(c.maxStepsPerFrame, 3);
    EXPECT_EQ(c.randomSeed, 1234u);
    EXPECT_EQ(c.maxFrameTime, 0.1);
    EXPECT_TRUE(c.debugDraw);
    EXPECT_EQ(c.debugDrawKey, "f3");
    EXPECT_FALSE(c.printProfile);
    EXPECT_TRUE(c.showProfile);
    EXPECT_EQ(c.profileKey, "f5");
}

TEST(EngineConfig, PhysicsKeysAreSIWhateverTheUnitsPerMetre) {
    const EngineConfigResult r = loadEngineConfig(kData / "every_key.txt", true);
    const physics::WorldDef def = engine::makeWorldDef(r.config);
    // At 100 units per metre as at any other scale: m/s^2, m/s and m, as written.
    EXPECT_FLOAT_EQ(def.gravity.x, 0.5f);
    EXPECT_FLOAT_EQ(def.gravity.y, -10.0f);
    EXPECT_EQ(def.solver.mode, physics::SolverMode::Classic);
    EXPECT_EQ(def.solver.subSteps, 10);
    EXPECT_EQ(def.solver.velocityIterations, 10);
    EXPECT_FLOAT_EQ(def.solver.linearSleepTolerance, 0.05f);
    EXPECT_EQ(def.workerCount, 2);
    // 1 mm of allowed penetration; the bias factor has no unit.
    EXPECT_FLOAT_EQ(def.solver.classicAllowedPenetration, 0.001f);
    EXPECT_FLOAT_EQ(def.solver.classicPositionBias, 0.1f);

    // The defaults give the library's own gravity direction and the config's value.
    const physics::WorldDef defaults = engine::makeWorldDef(engine::EngineConfig{});
    EXPECT_EQ(defaults.gravity.x, 0.0f);
    EXPECT_FLOAT_EQ(defaults.gravity.y, engine::EngineConfig{}.gravityY);
    EXPECT_EQ(defaults.solver.subSteps, engine::EngineConfig{}.collisionResolutionSteps);
    EXPECT_EQ(defaults.solver.mode, physics::SolverMode::SoftStep);
    EXPECT_EQ(defaults.workerCount, 1);
    // The seed's position-correction defaults are the classic solver's own, bit for bit.
    EXPECT_EQ(defaults.solver.classicAllowedPenetration,
              physics::SolverDef{}.classicAllowedPenetration);
    EXPECT_EQ(defaults.solver.classicPositionBias, physics::SolverDef{}.classicPositionBias);

    // More allowed penetration than the solver takes is capped; a bias factor of 0 (no
    // position correction) reaches the world as 0.
    engine::EngineConfig loose;
    loose.unitsPerMetre = 100.0;
    loose.allowedPenetration = 0.5f; // m
    loose.penetrationBiasFactor = 0.0f;
    const physics::WorldDef looseDef = engine::makeWorldDef(loose);
    EXPECT_EQ(looseDef.solver.classicAllowedPenetration, physics::kMaxClassicAllowedPenetration);
    EXPECT_EQ(looseDef.solver.classicPositionBias, 0.0f);
    EXPECT_NO_THROW(physics::World{looseDef});

    // More steps than the soft-step solver takes are capped, not an error.
    engine::EngineConfig many;
    many.collisionResolutionSteps = 100;
    EXPECT_EQ(engine::makeWorldDef(many).solver.subSteps, 64);
    EXPECT_EQ(engine::makeWorldDef(many).solver.velocityIterations, 100);
    // A world can be made from any valid config.
    EXPECT_NO_THROW(physics::World{engine::makeWorldDef(many)});
    EXPECT_NO_THROW(physics::World{engine::makeWorldDef(r.config)});
}

// The obvious pixel game, written with the defaults: world units are reference pixels, a crate
// dropped from the top of a 624-px view must fall like one (it used to fall 9 px in 80 frames:
// 9.81 units/s^2 at 1 unit per metre).
TEST(EngineConfig, DefaultsMakeAPixelCrateFallAsItLooks) {
    const engine::EngineConfig defaults;
    physics::World world{engine::makeWorldDef(defaults)};
    physics::BodyDef crate;
    crate.type = physics::BodyType::Dynamic;
    const physics::BodyId body = world.createBody(crate);
    world.createShape(body, {}, physics::makeBox(0.16f, 0.16f)); // 32 px at 100 px per metre
    for (int i = 0; i < 80; ++i) {
        world.step(1.0f / 60.0f);
    }
    const float fallenPixels =
        -world.transform(body).p.y * static_cast<float>(defaults.unitsPerMetre);
    // 1/2 g t^2 with g = 9.81 m/s^2 = 981 px/s^2 and t = 80/60 s: about 872 px.
    EXPECT_NEAR(fallenPixels, 0.5f * 981.0f * (80.0f / 60.0f) * (80.0f / 60.0f), 15.0f);
    EXPECT_EQ(defaults.unitsPerMetre, 100.0);
    EXPECT_FLOAT_EQ(defaults.gravityY, -9.81f);
}

TEST(EngineConfig, PenetrationKeysTuneAClassicWorld) {
    // A unit box spawned 10 cm into the ground of a classic-solver world made from a config:
    // the position iterations lift it until the allowed penetration is left (2 cm, whatever
    // the units per metre); with a bias factor of 0 it is not lifted at all.
    const auto overlapAfter = [](float allowedPenetration, float biasFactor, int steps) {
        engine::EngineConfig config;
        config.unitsPerMetre = 100.0;
        config.gravityY = -10.0f;
        config.allowedPenetration = allowedPenetration;
        config.penetrationBiasFactor = biasFactor;
        config.physicsSolver = physics::SolverMode::Classic;
        physics::World world{engine::makeWorldDef(config)};
        const physics::BodyId ground = world.createBody({});
        world.createShape(ground, {}, physics::makeOffsetBox(10.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
        physics::BodyDef bd;
        bd.type = physics::BodyType::Dynamic;
        bd.position = {0.0f, 0.4f};
        const physics::BodyId box = world.createBody(bd);
        world.createShape(box, {}, physics::makeBox(0.5f, 0.5f));
        for (int i = 0; i < steps; ++i) {
            world.step(1.0f / 60.0f);
        }
        return 0.5f - world.transform(box).p.y; // metres; the ground's top is y = 0
    };
    EXPECT_NEAR(overlapAfter(0.02f, 0.2f, 300), 0.02f, 1e-3f);
    EXPECT_NEAR(overlapAfter(0.005f, 0.2f, 300), 0.005f, 1e-3f);
    // A smaller factor corrects more slowly; 0 leaves the overlap as it was.
    EXPECT_GT(overlapAfter(0.005f, 0.05f, 6), overlapAfter(0.005f, 0.2f, 6) + 0.02f);
    EXPECT_NEAR(overlapAfter(0.005f, 0.0f, 6), 0.1f, 1e-5f);
}

TEST(EngineConfig, BadValuesAreErrorsNamingFileLineAndKey) {
    const std::filesystem::path path = writeTemp("bad.txt", "#DISPLAY\n"
                                                            "windowWidth = wide\n"
                                                            "screenFitMode = stretch\n"
                                                            "msaaSamples = -1\n"
                                                            "#PHYSICS\n"
                                                            "fixedTimestep = 0\n"
                                                            "unitsPerMetre = -100\n"
                                                            "vsync = maybe\n"
                                                            "this line has no equals sign\n"
                                                            "voiceCount = 2000\n"
                                                            "physicsWorkers = 0\n");
    const EngineConfigResult r = loadEngineConfig(path, true);
    const std::string f = path.string();
    EXPECT_THAT(
        errors(r),
        ElementsAre(
            f + ":2: windowWidth: expected an integer, got 'wide'",
            f + ":3: screenFitMode: unknown value 'stretch', expected one of: expand, widthFit, "
                "heightFit, bestFit",
            f + ":4: msaaSamples: must be in [0, 16], got -1",
            f + ":6: fixedTimestep: must be in (0, 1], got 0",
            f + ":7: unitsPerMetre: must be > 0, got -100",
            f + ":8: vsync: expected true or false, got 'maybe'",
            f + ":9: expected 'key = value', got 'this line has no equals sign'",
            f + ":10: voiceCount: must be in [1, 1024], got 2000",
            f + ":11: physicsWorkers: must be in [1, 64], got 0"));
    EXPECT_THAT(warnings(r), IsEmpty());
}

TEST(EngineConfig, UnknownAndDuplicateKeysAreWarningsWithTheirLine) {
    const std::filesystem::path path = writeTemp(
        "warn.txt",
        "firstScene = A\nwindowWidht = 800\nfirstScene = B\n\n  gravityZ = 3\nphysicsWorker = 2\n");
    const EngineConfigResult r = loadEngineConfig(path, true);
    const std::string f = path.string();
    EXPECT_THAT(errors(r), IsEmpty());
    EXPECT_THAT(
        warnings(r),
        ElementsAre(
            f + ":2: windowWidht: unknown key, ignored (did you mean 'windowWidth'?)",
            f + ":3: firstScene: duplicate key, replaces the value set on line 1",
            f + ":5: gravityZ: unknown key, ignored (did you mean 'gravityX'?)",
            f + ":6: physicsWorker: unknown key, ignored (did you mean 'physicsWorkers'?)"));
    EXPECT_EQ(r.config.firstScene, "B");
    EXPECT_EQ(r.config.windowWidth, engine::EngineConfig{}.windowWidth);
}

TEST(EngineConfig, MissingFileIsAnErrorOnlyWhenRequired) {
    const std::filesystem::path missing = kData / "no-such-config.txt";
    const EngineConfigResult required = loadEngineConfig(missing, true);
    EXPECT_THAT(
        errors(required),
        ElementsAre(missing.string() + ": cannot read the configuration file (no such file)"));
    const EngineConfigResult optional = loadEngineConfig(missing, false);
    EXPECT_THAT(errors(optional), IsEmpty());
    EXPECT_THAT(
        warnings(optional),
        ElementsAre(missing.string() +
                    ": cannot read the configuration file (no such file), using the defaults"));
    EXPECT_EQ(optional.config.windowWidth, engine::EngineConfig{}.windowWidth);
    EXPECT_TRUE(optional.config.file.empty());
    // A folder is not a configuration file.
    EXPECT_THAT(errors(loadEngineConfig(kData, true)),
                ElementsAre(HasSubstr("cannot read the configuration file (it is a directory)")));
}

// --- The game's keys through the text reader (each key's range, enums, checks across keys) ---

TEST(EngineConfig, EveryErrorKindWithItsLineNumberAndWrongValuesKeepTheirDefaults) {
    const EngineConfigResult r =
        engine::parseEngineConfig("windowWidth = abc\n"                   // 1: not a number
                                  "windowHeight = 12px\n"                 // 2: trailing junk
                                  "fontSize = 1.5\n"                      // 3: not an integer
                                  "referenceWindowWidth = -5\n"           // 4: below its minimum
                                  "referenceWindowHeight = 99999999999\n" // 5: overflows int
                                  "screenFitMode = stretch\n"             // 6: unknown enum value
                                  "just some words\n"                     // 7: missing '='
                                  " = 5\n"                                // 8: empty key
                                  "masterGain = -0.5\n"                   // 9: below minimum
                                  "penetrationBiasFactor = 2\n"           // 10: above maximum
                                  "fixedTimestep = 0\n"                   // 11: must be > 0
                                  "gravityY = inf\n"                      // 12: not finite
                                  "maxCameraDepth = 1e60\n"               // 13: overflows float
                                  "collisionResolutionSteps =\n",         // 14: empty value
                                  "game.cfg");
    EXPECT_THAT(
        errors(r),
        ElementsAre("game.cfg:1: windowWidth: expected an integer, got 'abc'",
                    "game.cfg:2: windowHeight: expected an integer, got '12px'",
                    "game.cfg:3: fontSize: expected an integer, got '1.5'",
                    "game.cfg:4: referenceWindowWidth: must be >= 1, got -5",
                    "game.cfg:5: referenceWindowHeight: integer out of range, got '99999999999'",
                    "game.cfg:6: screenFitMode: unknown value 'stretch', expected one of: expand, "
                    "widthFit, "
                    "heightFit, bestFit",
                    "game.cfg:7: expected 'key = value', got 'just some words'",
                    "game.cfg:8: empty key before '=' in '= 5'",
                    "game.cfg:9: masterGain: must be >= 0, got -0.5",
                    "game.cfg:10: penetrationBiasFactor: must be in [0, 1], got 2",
                    "game.cfg:11: fixedTimestep: must be in (0, 1], got 0",
                    "game.cfg:12: gravityY: expected a finite number, got 'inf'",
                    "game.cfg:13: maxCameraDepth: number out of range, got '1e60'",
                    "game.cfg:14: collisionResolutionSteps: expected an integer, got ''"));
    const engine::EngineConfig defaults;
    EXPECT_EQ(r.config.windowWidth, defaults.windowWidth);
    EXPECT_EQ(r.config.referenceWindowWidth, defaults.referenceWindowWidth);
    EXPECT_EQ(r.config.screenFitMode, defaults.screenFitMode);
    EXPECT_EQ(r.config.masterGain, defaults.masterGain);
    EXPECT_EQ(r.config.fixedTimestep, defaults.fixedTimestep);
    EXPECT_EQ(r.config.gravityY, defaults.gravityY);
}

TEST(EngineConfig, EnumsAreTheLibrariesOwnTypesSpelledAsInTheFile) {
    const EngineConfigResult r =
        engine::parseEngineConfig("screenFitMode = expand\nwindowMode = borderless\n"
                                  "textureFilteringMode = linear\nphysicsSolver = classic\n");
    EXPECT_THAT(errors(r), IsEmpty());
    EXPECT_EQ(r.config.screenFitMode, render::ScreenFit::Expand);
    EXPECT_EQ(r.config.windowMode, render::WindowMode::Borderless);
    EXPECT_EQ(r.config.textureFilteringMode, render::TextureFilter::Linear);
    EXPECT_EQ(r.config.physicsSolver, physics::SolverMode::Classic);
    EXPECT_EQ(engine::parseEngineConfig("screenFitMode = bestFit").config.screenFitMode,
              render::ScreenFit::BestFit);
    EXPECT_THAT(
        errors(engine::parseEngineConfig("windowMode = Windowed\ntextureFilteringMode = bilinear\n"
                                         "physicsSolver = box2d",
                                         "c")),
        ElementsAre(
            "c:1: windowMode: unknown value 'Windowed', expected one of: windowed, fullscreen, "
            "borderless",
            "c:2: textureFilteringMode: unknown value 'bilinear', expected one of: nearest, linear",
            "c:3: physicsSolver: unknown value 'box2d', expected one of: softStep, classic"));
}

TEST(EngineConfig, MinAboveMaxIsBlamedOnTheLaterKeyAndResetsBoth) {
    const EngineConfigResult r = engine::parseEngineConfig("minAttenuationDistance = 600\n"
                                                           "maxAttenuationDistance = 500\n"
                                                           "minPanningDistance = 700\n",
                                                           "game.cfg");
    EXPECT_THAT(
        errors(r),
        ElementsAre(
            "game.cfg:2: maxAttenuationDistance: must be >= minAttenuationDistance (600), got 500",
            "game.cfg:3: minPanningDistance: must be <= maxPanningDistance (512), got 700"));
    EXPECT_EQ(r.config.minAttenuationDistance, 256.0f);
    EXPECT_EQ(r.config.maxAttenuationDistance, 512.0f);
    EXPECT_EQ(r.config.minPanningDistance, 256.0f);
    EXPECT_THAT(errors(engine::parseEngineConfig("minPanningDistance = 512")), IsEmpty());
}

TEST(EngineConfig, E2dKeysBadValuesNameLineAndKey) {
    const EngineConfigResult r =
        engine::parseEngineConfig("vsync = yes\nmsaaSamples = 17\nunitsPerMetre = 0\n"
                                  "voiceCount = 0\nkeyRepeat = 1\nmaxFrameTime = 11\n",
                                  "g.cfg");
    EXPECT_THAT(errors(r), ElementsAre("g.cfg:1: vsync: expected true or false, got 'yes'",
                                       "g.cfg:2: msaaSamples: must be in [0, 16], got 17",
                                       "g.cfg:3: unitsPerMetre: must be > 0, got 0",
                                       "g.cfg:4: voiceCount: must be in [1, 1024], got 0",
                                       "g.cfg:5: keyRepeat: expected true or false, got '1'",
                                       "g.cfg:6: maxFrameTime: must be in (0, 10], got 11"));
}

} // namespace
