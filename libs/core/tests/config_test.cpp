// SPDX-License-Identifier: MIT
#include <e2d/core/config.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using e2d::core::Config;
using e2d::core::ConfigDiagnostic;
using e2d::core::ConfigResult;
using e2d::core::loadConfig;
using e2d::core::parseConfig;
using e2d::core::PhysicsSolver;
using e2d::core::ScreenFitMode;
using e2d::core::TextureFilteringMode;
using e2d::core::WindowMode;
using Severity = e2d::core::ConfigDiagnostic::Severity;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;

namespace {

std::vector<std::string> texts(const ConfigResult& result) {
    std::vector<std::string> out;
    for (const ConfigDiagnostic& d : result.diagnostics) {
        out.push_back(d.toString());
    }
    return out;
}

// Figure 107 of the seed report, physics in metres.
constexpr const char* kFigure107 = R"(#SCENE
firstScene = CollisionTestScene

#DISPLAY
referenceWindowWidth = 1024
referenceWindowHeight = 624
windowWidth = 1024
windowHeight = 624
screenFitMode = widthFit
windowMode = windowed
windowTitle = test
textureFilteringMode = nearest
maxCameraDepth = 1000

#TEXT
fontSize = 100

#PHYSICS
gravityX = 0
gravityY = -9.81
fixedTimestep = 0.005
collisionResolutionSteps = 10
allowedPenetration = 0.1
penetrationBiasFactor = 0.1
minRigidbodySpeed = 5

#SOUND
minAttenuationDistance = 256
maxAttenuationDistance = 512
minPanningDistance = 256
maxPanningDistance = 512
masterGain = 0.2
)";

} // namespace

TEST(Config, Defaults) {
    const Config c;
    EXPECT_EQ(c.firstScene, "");
    EXPECT_EQ(c.referenceWindowWidth, 1024);
    EXPECT_EQ(c.referenceWindowHeight, 624);
    EXPECT_EQ(c.windowWidth, 1024);
    EXPECT_EQ(c.windowHeight, 624);
    EXPECT_EQ(c.screenFitMode, ScreenFitMode::WidthFit);
    EXPECT_EQ(c.windowMode, WindowMode::Windowed);
    EXPECT_EQ(c.textureFilteringMode, TextureFilteringMode::Nearest);
    EXPECT_EQ(c.maxCameraDepth, 1000.0f);
    EXPECT_EQ(c.fontSize, 100);
    EXPECT_EQ(c.gravityX, 0.0f);
    EXPECT_EQ(c.gravityY, -9.81f);
    EXPECT_EQ(c.fixedTimestep, 1.0 / 60.0);
    EXPECT_EQ(c.collisionResolutionSteps, 4);
    EXPECT_EQ(c.allowedPenetration, 0.005f);
    EXPECT_EQ(c.penetrationBiasFactor, 0.2f);
    EXPECT_EQ(c.minRigidbodySpeed, 0.05f);
    EXPECT_EQ(c.minAttenuationDistance, 256.0f);
    EXPECT_EQ(c.maxAttenuationDistance, 512.0f);
    EXPECT_EQ(c.minPanningDistance, 256.0f);
    EXPECT_EQ(c.maxPanningDistance, 512.0f);
    EXPECT_EQ(c.masterGain, 0.2f);
    EXPECT_EQ(c.maxStepsPerFrame, 5);
    EXPECT_EQ(c.randomSeed, 0u);
}

TEST(Config, ParsesTheSeedFigure) {
    const ConfigResult r = parseConfig(kFigure107, "game.cfg");
    EXPECT_THAT(texts(r), IsEmpty());
    const Config& c = r.config;
    EXPECT_EQ(c.firstScene, "CollisionTestScene");
    EXPECT_EQ(c.windowTitle, "test");
    EXPECT_EQ(c.fixedTimestep, 0.005);
    EXPECT_EQ(c.collisionResolutionSteps, 10);
    EXPECT_EQ(c.allowedPenetration, 0.1f);
    EXPECT_EQ(c.penetrationBiasFactor, 0.1f);
    EXPECT_EQ(c.minRigidbodySpeed, 5.0f);
    EXPECT_EQ(c.gravityY, -9.81f);
    EXPECT_FALSE(r.hasErrors());
    EXPECT_FALSE(r.hasWarnings());
}

TEST(Config, EveryEnumValue) {
    const ConfigResult r = parseConfig("screenFitMode = expand\nwindowMode = fullscreen\ntextureFilteringMode = linear\n");
    EXPECT_THAT(texts(r), IsEmpty());
    EXPECT_EQ(r.config.screenFitMode, ScreenFitMode::Expand);
    EXPECT_EQ(r.config.windowMode, WindowMode::Fullscreen);
    EXPECT_EQ(r.config.textureFilteringMode, TextureFilteringMode::Linear);
    EXPECT_EQ(parseConfig("screenFitMode = heightFit").config.screenFitMode, ScreenFitMode::HeightFit);
    EXPECT_EQ(parseConfig("screenFitMode = bestFit").config.screenFitMode, ScreenFitMode::BestFit);
    EXPECT_EQ(Config{}.physicsSolver, PhysicsSolver::SoftStep);
    EXPECT_EQ(parseConfig("physicsSolver = classic").config.physicsSolver, PhysicsSolver::Classic);
    EXPECT_EQ(parseConfig("physicsSolver = softStep").config.physicsSolver, PhysicsSolver::SoftStep);
    EXPECT_EQ(toString(PhysicsSolver::Classic), "classic");
    const ConfigResult bad = parseConfig("physicsSolver = box2d\n", "game.cfg");
    ASSERT_TRUE(bad.hasErrors());
    EXPECT_THAT(texts(bad)[0], HasSubstr("game.cfg:1"));
    EXPECT_THAT(texts(bad)[0], HasSubstr("physicsSolver"));
    EXPECT_EQ(bad.config.physicsSolver, PhysicsSolver::SoftStep);
    EXPECT_EQ(e2d::core::toString(ScreenFitMode::BestFit), "bestFit");
    EXPECT_EQ(e2d::core::toString(WindowMode::Fullscreen), "fullscreen");
    EXPECT_EQ(e2d::core::toString(TextureFilteringMode::Linear), "linear");
}

TEST(Config, WhitespaceCommentsSpacesInValuesAndCrlf) {
    const ConfigResult r = parseConfig("\xEF\xBB\xBF# comment\r\n"
                                       "   \t\r\n"
                                       "  windowTitle   =   My  Game # not a comment  \r\n"
                                       "\twindowWidth=800\r\n"
                                       "   # indented comment\n"
                                       "randomSeed = 18446744073709551615\n"
                                       "gravityX = +1.5e1",
                                       "game.cfg");
    EXPECT_THAT(texts(r), IsEmpty());
    EXPECT_EQ(r.config.windowTitle, "My  Game # not a comment");
    EXPECT_EQ(r.config.windowWidth, 800);
    EXPECT_EQ(r.config.randomSeed, 18446744073709551615ull);
    EXPECT_EQ(r.config.gravityX, 15.0f);
}

TEST(Config, EveryErrorKindWithItsLineNumber) {
    const ConfigResult r = parseConfig("windowWidth = abc\n"              // 1: not a number
                                       "windowHeight = 12px\n"            // 2: trailing junk
                                       "fontSize = 1.5\n"                 // 3: not an integer
                                       "referenceWindowWidth = -5\n"      // 4: out of range (negative size)
                                       "referenceWindowHeight = 99999999999\n" // 5: overflows int
                                       "screenFitMode = stretch\n"        // 6: unknown enum value
                                       "just some words\n"                // 7: missing '='
                                       " = 5\n"                           // 8: empty key
                                       "masterGain = -0.5\n"              // 9: below minimum
                                       "penetrationBiasFactor = 2\n"      // 10: above maximum
                                       "fixedTimestep = 0\n"              // 11: must be > 0
                                       "gravityY = inf\n"                 // 12: not finite
                                       "maxCameraDepth = 1e60\n"          // 13: overflows float
                                       "collisionResolutionSteps =\n",    // 14: empty value
                                       "game.cfg");
    EXPECT_THAT(texts(r),
                ElementsAre("game.cfg:1: windowWidth: expected an integer, got 'abc'",
                            "game.cfg:2: windowHeight: expected an integer, got '12px'",
                            "game.cfg:3: fontSize: expected an integer, got '1.5'",
                            "game.cfg:4: referenceWindowWidth: must be >= 1, got -5",
                            "game.cfg:5: referenceWindowHeight: integer out of range, got '99999999999'",
                            "game.cfg:6: screenFitMode: unknown value 'stretch', expected one of: expand, widthFit, "
                            "heightFit, bestFit",
                            "game.cfg:7: expected 'key = value', got 'just some words'",
                            "game.cfg:8: empty key before '=' in '= 5'",
                            "game.cfg:9: masterGain: must be >= 0, got -0.5",
                            "game.cfg:10: penetrationBiasFactor: must be in [0, 1], got 2",
                            "game.cfg:11: fixedTimestep: must be in (0, 1], got 0",
                            "game.cfg:12: gravityY: expected a finite number, got 'inf'",
                            "game.cfg:13: maxCameraDepth: number out of range, got '1e60'",
                            "game.cfg:14: collisionResolutionSteps: expected an integer, got ''"));
    for (const ConfigDiagnostic& d : r.diagnostics) {
        EXPECT_EQ(d.severity, Severity::Error);
        EXPECT_EQ(d.file, "game.cfg");
    }
    EXPECT_EQ(r.diagnostics[0].line, 1);
    EXPECT_EQ(r.diagnostics[0].key, "windowWidth");
    EXPECT_EQ(r.diagnostics[0].message, "expected an integer, got 'abc'");
    EXPECT_EQ(r.diagnostics[6].key, "");
    EXPECT_TRUE(r.hasErrors());
    EXPECT_FALSE(r.hasWarnings());

    // Wrong values keep their defaults.
    const Config defaults;
    EXPECT_EQ(r.config.windowWidth, defaults.windowWidth);
    EXPECT_EQ(r.config.windowHeight, defaults.windowHeight);
    EXPECT_EQ(r.config.referenceWindowWidth, defaults.referenceWindowWidth);
    EXPECT_EQ(r.config.screenFitMode, defaults.screenFitMode);
    EXPECT_EQ(r.config.masterGain, defaults.masterGain);
    EXPECT_EQ(r.config.fixedTimestep, defaults.fixedTimestep);
    EXPECT_EQ(r.config.gravityY, defaults.gravityY);
    EXPECT_EQ(r.config.collisionResolutionSteps, defaults.collisionResolutionSteps);
}

TEST(Config, UnknownEnumListsTheAcceptedValuesOfEachEnum) {
    const ConfigResult r = parseConfig("windowMode = Windowed\ntextureFilteringMode = bilinear", "c");
    EXPECT_THAT(texts(r), ElementsAre("c:1: windowMode: unknown value 'Windowed', expected one of: windowed, fullscreen",
                                      "c:2: textureFilteringMode: unknown value 'bilinear', expected one of: nearest, "
                                      "linear"));
}

TEST(Config, WarningsForUnknownAndDuplicateKeys) {
    const ConfigResult r = parseConfig("windowWidth = 800\n"
                                       "windowWidht = 900\n"
                                       "\n"
                                       "windowWidth = 640\n",
                                       "game.cfg");
    EXPECT_THAT(texts(r), ElementsAre("game.cfg:2: windowWidht: unknown key, ignored",
                                      "game.cfg:4: windowWidth: duplicate key, replaces the value set on line 1"));
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[1].severity, Severity::Warning);
    EXPECT_EQ(r.config.windowWidth, 640); // the last one wins
    EXPECT_FALSE(r.hasErrors());
    EXPECT_TRUE(r.hasWarnings());
}

TEST(Config, MinAboveMaxIsBlamedOnTheLaterKeyAndResetsBoth) {
    const ConfigResult r = parseConfig("minAttenuationDistance = 600\n"
                                       "maxAttenuationDistance = 500\n"
                                       "minPanningDistance = 700\n",
                                       "game.cfg");
    EXPECT_THAT(texts(r),
                ElementsAre("game.cfg:2: maxAttenuationDistance: must be >= minAttenuationDistance (600), got 500",
                            "game.cfg:3: minPanningDistance: must be <= maxPanningDistance (512), got 700"));
    EXPECT_EQ(r.config.minAttenuationDistance, 256.0f);
    EXPECT_EQ(r.config.maxAttenuationDistance, 512.0f);
    EXPECT_EQ(r.config.minPanningDistance, 256.0f);
    // Equal bounds are fine.
    EXPECT_THAT(parseConfig("minPanningDistance = 512").diagnostics, IsEmpty());
}

TEST(Config, EmptyTextGivesDefaults) {
    const ConfigResult r = parseConfig("", "empty.cfg");
    EXPECT_THAT(r.diagnostics, IsEmpty());
    EXPECT_EQ(r.config.windowWidth, 1024);
}

TEST(Config, MissingFileWarnsAndUsesDefaults) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "e2d-core-test-does-not-exist.cfg";
    const ConfigResult r = loadConfig(path);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[0].line, 0);
    EXPECT_EQ(r.diagnostics[0].toString(), path.string() + ": cannot read the file, using the defaults");
    EXPECT_EQ(r.config.windowHeight, 624);
}

TEST(Config, LoadsAFile) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "e2d-core-test-load.cfg";
    {
        std::ofstream out(path, std::ios::binary);
        out << "# test\nwindowTitle = Loaded Game\nfontSize = x\n";
    }
    const ConfigResult r = loadConfig(path);
    std::filesystem::remove(path);
    EXPECT_EQ(r.config.windowTitle, "Loaded Game");
    EXPECT_THAT(texts(r), ElementsAre(path.string() + ":3: fontSize: expected an integer, got 'x'"));
}

TEST(Config, DirectoryIsNotAConfigFile) {
    const ConfigResult r = loadConfig(std::filesystem::temp_directory_path());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
}

TEST(Config, E2dKeysDefaultsAndValues) {
    const Config d;
    EXPECT_TRUE(d.vsync);
    EXPECT_EQ(d.msaaSamples, 0);
    EXPECT_EQ(d.unitsPerMetre, 1.0);
    EXPECT_EQ(d.voiceCount, 32);
    EXPECT_EQ(d.bindingsFile, "");
    EXPECT_TRUE(d.keyRepeat);
    EXPECT_EQ(d.maxFrameTime, 0.25);
    EXPECT_FALSE(d.debugDraw);
    EXPECT_EQ(d.debugDrawKey, "f1");
    EXPECT_TRUE(d.printProfile);
    EXPECT_FALSE(d.showProfile);
    EXPECT_EQ(d.profileKey, "f2");

    const ConfigResult r = parseConfig("vsync = false\nmsaaSamples = 4\nunitsPerMetre = 100\nvoiceCount = 64\n"
                                       "bindingsFile = keys/bindings.txt\nkeyRepeat = false\nmaxFrameTime = 0.1\n"
                                       "debugDraw = true\ndebugDrawKey = tab\nprintProfile = false\n"
                                       "showProfile = true\nprofileKey = f4\n");
    EXPECT_THAT(texts(r), IsEmpty());
    EXPECT_FALSE(r.config.vsync);
    EXPECT_EQ(r.config.msaaSamples, 4);
    EXPECT_EQ(r.config.unitsPerMetre, 100.0);
    EXPECT_EQ(r.config.voiceCount, 64);
    EXPECT_EQ(r.config.bindingsFile, "keys/bindings.txt");
    EXPECT_FALSE(r.config.keyRepeat);
    EXPECT_EQ(r.config.maxFrameTime, 0.1);
    EXPECT_TRUE(r.config.debugDraw);
    EXPECT_EQ(r.config.debugDrawKey, "tab");
    EXPECT_FALSE(r.config.printProfile);
    EXPECT_TRUE(r.config.showProfile);
    EXPECT_EQ(r.config.profileKey, "f4");
}

TEST(Config, E2dKeysBadValuesNameLineAndKey) {
    const ConfigResult r = parseConfig("vsync = yes\nmsaaSamples = 17\nunitsPerMetre = 0\nvoiceCount = 0\n"
                                       "keyRepeat = 1\nmaxFrameTime = 11\n",
                                       "g.cfg");
    EXPECT_THAT(texts(r), ElementsAre("g.cfg:1: vsync: expected true or false, got 'yes'",
                                      "g.cfg:2: msaaSamples: must be in [0, 16], got 17",
                                      "g.cfg:3: unitsPerMetre: must be > 0, got 0",
                                      "g.cfg:4: voiceCount: must be in [1, 1024], got 0",
                                      "g.cfg:5: keyRepeat: expected true or false, got '1'",
                                      "g.cfg:6: maxFrameTime: must be in (0, 10], got 11"));
    const Config d;
    EXPECT_EQ(r.config.vsync, d.vsync);
    EXPECT_EQ(r.config.msaaSamples, d.msaaSamples);
    EXPECT_EQ(r.config.unitsPerMetre, d.unitsPerMetre);
}
