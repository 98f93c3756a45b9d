// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using e2d::core::Error;
using e2d::render::PixelRect;
using e2d::render::SpriteFrame;
using e2d::render::SpriteSheet;
using testing::HasSubstr;

namespace {

// One untrimmed, one trimmed and one rotated + trimmed frame on a 128x64 image, hash format.
const char* const kHash = R"({
  "frames": {
    "idle.png": {"frame": {"x": 0, "y": 0, "w": 32, "h": 16}, "rotated": false, "trimmed": false,
                 "spriteSourceSize": {"x": 0, "y": 0, "w": 32, "h": 16}, "sourceSize": {"w": 32, "h": 16}},
    "jump.png": {"frame": {"x": 32, "y": 8, "w": 20, "h": 30}, "rotated": false, "trimmed": true,
                 "spriteSourceSize": {"x": 6, "y": 1, "w": 20, "h": 30}, "sourceSize": {"w": 32, "h": 32},
                 "pivot": {"x": 0.25, "y": 1}},
    "fall.png": {"frame": {"x": 64, "y": 0, "w": 40, "h": 10}, "rotated": true, "trimmed": true,
                 "spriteSourceSize": {"x": 2, "y": 3, "w": 40, "h": 10}, "sourceSize": {"w": 48, "h": 16}}
  },
  "meta": {"app": "test", "image": "hero.png", "format": "RGBA8888", "size": {"w": 128, "h": 64}, "scale": "1"}
})";

// The same frames in the array format.
const char* const kArray = R"({
  "frames": [
    {"filename": "idle.png", "frame": {"x": 0, "y": 0, "w": 32, "h": 16}, "rotated": false, "trimmed": false,
     "spriteSourceSize": {"x": 0, "y": 0, "w": 32, "h": 16}, "sourceSize": {"w": 32, "h": 16}},
    {"filename": "jump.png", "frame": {"x": 32, "y": 8, "w": 20, "h": 30}, "rotated": false, "trimmed": true,
     "spriteSourceSize": {"x": 6, "y": 1, "w": 20, "h": 30}, "sourceSize": {"w": 32, "h": 32},
     "pivot": {"x": 0.25, "y": 1}},
    {"filename": "fall.png", "frame": {"x": 64, "y": 0, "w": 40, "h": 10}, "rotated": true, "trimmed": true,
     "spriteSourceSize": {"x": 2, "y": 3, "w": 40, "h": 10}, "sourceSize": {"w": 48, "h": 16}}
  ],
  "meta": {"image": "hero.png", "size": {"w": 128, "h": 64}}
})";

void expectHeroFrames(const SpriteSheet& sheet) {
    EXPECT_EQ(sheet.imageSize(), glm::ivec2(128, 64));
    EXPECT_EQ(sheet.imagePath(), std::filesystem::path("assets") / "hero.png");
    ASSERT_EQ(sheet.frames().size(), 3u);
    EXPECT_EQ(sheet.frames()[0].name, "idle.png");
    EXPECT_EQ(sheet.frames()[1].name, "jump.png");
    EXPECT_EQ(sheet.frames()[2].name, "fall.png");

    const SpriteFrame& idle = sheet.frame("idle.png");
    EXPECT_EQ(idle.region, (PixelRect{0, 0, 32, 16}));
    EXPECT_FALSE(idle.rotated);
    EXPECT_FALSE(idle.trimmed);
    EXPECT_EQ(idle.size(), glm::ivec2(32, 16));
    EXPECT_EQ(idle.trimOffset(), glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(idle.pivot, glm::vec2(0.5f, 0.5f));
    // Top-left 32x16 of a 128x64 image, top-left origin.
    EXPECT_FLOAT_EQ(idle.uv.min.x, 0.0f);
    EXPECT_FLOAT_EQ(idle.uv.min.y, 0.0f);
    EXPECT_FLOAT_EQ(idle.uv.max().x, 32.0f / 128.0f);
    EXPECT_FLOAT_EQ(idle.uv.max().y, 16.0f / 64.0f);

    const SpriteFrame& jump = sheet.frame("jump.png");
    EXPECT_TRUE(jump.trimmed);
    EXPECT_EQ(jump.region, (PixelRect{32, 8, 20, 30}));
    EXPECT_EQ(jump.trimRect, (PixelRect{6, 1, 20, 30}));
    EXPECT_EQ(jump.sourceSize, glm::ivec2(32, 32));
    EXPECT_EQ(jump.pivot, glm::vec2(0.25f, 1.0f));
    // Trimmed centre (6 + 10, 1 + 15) = (16, 16) from the top-left; source centre (16, 16).
    EXPECT_EQ(jump.trimOffset(), glm::vec2(0.0f, 0.0f));
    EXPECT_FLOAT_EQ(jump.uv.min.x, 32.0f / 128.0f);
    EXPECT_FLOAT_EQ(jump.uv.min.y, 8.0f / 64.0f);
    EXPECT_FLOAT_EQ(jump.uv.max().x, 52.0f / 128.0f);
    EXPECT_FLOAT_EQ(jump.uv.max().y, 38.0f / 64.0f);

    const SpriteFrame& fall = sheet.frame("fall.png");
    EXPECT_TRUE(fall.rotated);
    // Displayed 40x10, stored rotated: 10 wide and 40 tall in the image.
    EXPECT_EQ(fall.region, (PixelRect{64, 0, 10, 40}));
    EXPECT_EQ(fall.size(), glm::ivec2(40, 10));
    // Trimmed centre (2 + 20, 3 + 5) = (22, 8); source centre (24, 8): 2 px left, same height.
    EXPECT_EQ(fall.trimOffset(), glm::vec2(-2.0f, 0.0f));
    EXPECT_FLOAT_EQ(fall.uv.min.x, 64.0f / 128.0f);
    EXPECT_FLOAT_EQ(fall.uv.min.y, 0.0f);
    EXPECT_FLOAT_EQ(fall.uv.max().x, 74.0f / 128.0f);
    EXPECT_FLOAT_EQ(fall.uv.max().y, 40.0f / 64.0f);
}

std::string errorOf(const std::string& json, const std::string& name = "bad.json") {
    try {
        static_cast<void>(SpriteSheet::fromString(json, name));
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// A valid array sheet with `frame` replacing the one frame's body.
std::string
oneFrame(const std::string& body,
         const std::string& meta = R"({"image": "a.png", "size": {"w": 64, "h": 64}})") {
    return R"({"frames": {"a": )" + body + R"(}, "meta": )" + meta + "}";
}

} // namespace

TEST(SpriteSheet, ReadsTheHashFormatWithTrimmedAndRotatedFrames) {
    expectHeroFrames(SpriteSheet::fromString(kHash, "hero.json", "assets"));
}

TEST(SpriteSheet, ReadsTheArrayFormatAlike) {
    expectHeroFrames(SpriteSheet::fromString(kArray, "hero.json", "assets"));
}

TEST(SpriteSheet, ReadsAFileAndResolvesTheImageNextToIt) {
    const auto dir = std::filesystem::temp_directory_path() / "e2d_sheet_test";
    std::filesystem::create_directories(dir);
    const auto path = dir / "hero.json";
    std::ofstream(path) << kArray;
    const SpriteSheet sheet = SpriteSheet::fromFile(path);
    EXPECT_EQ(sheet.name(), path.string());
    EXPECT_EQ(sheet.imagePath(), dir / "hero.png");
    EXPECT_EQ(sheet.frames().size(), 3u);
}

TEST(SpriteSheet, AMissingFileIsAnErrorNamingIt) {
    EXPECT_THAT(errorOf("", "x"), HasSubstr("malformed JSON"));
    try {
        static_cast<void>(SpriteSheet::fromFile("/nonexistent/sheet.json"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(
            e.what(),
            "render::SpriteSheet: /nonexistent/sheet.json: cannot read the file (no such file)");
    }
}

TEST(SpriteSheet, OptionalKeysDefaultToAnUntrimmedUnrotatedFrame) {
    const SpriteSheet sheet =
        SpriteSheet::fromString(oneFrame(R"({"frame": {"x": 1, "y": 2, "w": 3, "h": 4}})"), "s");
    const SpriteFrame& f = sheet.frame("a");
    EXPECT_FALSE(f.rotated);
    EXPECT_FALSE(f.trimmed);
    EXPECT_EQ(f.trimRect, (PixelRect{0, 0, 3, 4}));
    EXPECT_EQ(f.sourceSize, glm::ivec2(3, 4));
    EXPECT_EQ(f.pivot, glm::vec2(0.5f, 0.5f));
}

TEST(SpriteSheet, LooksFramesUpByExactName) {
    const SpriteSheet sheet = SpriteSheet::fromString(kHash, "hero.json");
    EXPECT_NE(sheet.find("jump.png"), nullptr);
    EXPECT_EQ(sheet.find("jump"), nullptr);
    EXPECT_EQ(sheet.find(""), nullptr);
    try {
        static_cast<void>(sheet.frame("jump"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "render::SpriteSheet::frame(): 'hero.json' has no frame \"jump\"");
    }
}

TEST(SpriteSheet, AnimationFramesAreInNaturalNumericOrder) {
    // Written in a scrambled order; names that only share a prefix must not join in.
    const std::vector<std::string> names = {"run10.png",  "run2.png",  "running1.png", "run1.png",
                                            "run",        "run3x.png", "run002.png",   "walk1.png",
                                            "run100.png", "run9"};
    std::string json = R"({"frames": [)";
    for (std::size_t i = 0; i < names.size(); ++i) {
        json += (i ? "," : "") + std::string(R"({"filename": ")") + names[i] +
                R"(", "frame": {"x": 0, "y": 0, "w": 1, "h": 1}})";
    }
    json += R"(], "meta": {"image": "a.png", "size": {"w": 1, "h": 1}}})";
    const SpriteSheet sheet = SpriteSheet::fromString(json, "s");
    std::vector<std::string> order;
    for (int i : sheet.animationFrames("run")) {
        order.push_back(sheet.frames()[static_cast<std::size_t>(i)].name);
    }
    // 1, 2 (fewer digits first among equals), 002, 9, 10, 100.
    EXPECT_THAT(order, testing::ElementsAre("run1.png", "run2.png", "run002.png", "run9",
                                            "run10.png", "run100.png"));
    EXPECT_TRUE(sheet.animationFrames("jump").empty());
    EXPECT_EQ(sheet.animationFrames("walk").size(), 1u);
}

TEST(SpriteSheet, MalformedJsonNamesTheFileLineAndColumn) {
    EXPECT_THAT(errorOf("{\n  \"frames\": {,\n}", "sheets/bad.json"),
                testing::StartsWith("render::SpriteSheet: sheets/bad.json:2:14: malformed JSON: "));
    EXPECT_THAT(errorOf("{\"frames\": [", "t.json"),
                testing::StartsWith("render::SpriteSheet: t.json:1:"));
    // nlohmann reports a number beyond double's range differently (found by fuzz_sprite_sheet).
    EXPECT_EQ(errorOf("[1e99999]", "n.json"),
              "render::SpriteSheet: n.json: malformed JSON: number overflow parsing '1e99999'");
}

TEST(SpriteSheet, EveryMissingKeyIsNamedWithItsPath) {
    EXPECT_EQ(errorOf(R"({"frames": {}})"), "render::SpriteSheet: bad.json: missing key \"meta\"");
    EXPECT_EQ(errorOf(R"({"meta": {"image": "a.png", "size": {"w": 1, "h": 1}}})"),
              "render::SpriteSheet: bad.json: missing key \"frames\"");
    EXPECT_EQ(errorOf(R"({"frames": {}, "meta": {"size": {"w": 1, "h": 1}}})"),
              "render::SpriteSheet: bad.json: meta: missing key \"image\"");
    EXPECT_EQ(errorOf(R"({"frames": {}, "meta": {"image": "a.png", "size": {"w": 1}}})"),
              "render::SpriteSheet: bad.json: meta.size: missing key \"h\"");
    EXPECT_EQ(errorOf(oneFrame(R"({"rotated": false})")),
              "render::SpriteSheet: bad.json: frames[\"a\"]: missing key \"frame\"");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "h": 4}})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame: missing key \"w\"");
    EXPECT_EQ(
        errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 4, "h": 4}, "sourceSize": {"w": 4}})")),
        "render::SpriteSheet: bad.json: frames[\"a\"].sourceSize: missing key \"h\"");
    EXPECT_EQ(
        errorOf(
            R"({"frames": [{"frame": {"x": 0, "y": 0, "w": 1, "h": 1}}], "meta": {"image": "a", "size": {"w": 1, "h": 1}}})"),
        "render::SpriteSheet: bad.json: frames[0]: missing key \"filename\"");
    EXPECT_EQ(
        errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 4, "h": 4}, "pivot": {"x": 0.5}})")),
        "render::SpriteSheet: bad.json: frames[\"a\"].pivot: missing key \"y\"");
}

TEST(SpriteSheet, EveryWrongTypeIsNamedWithItsPathAndValue) {
    EXPECT_EQ(errorOf("[]"), "render::SpriteSheet: bad.json: expected an object, got array []");
    EXPECT_EQ(errorOf(R"({"frames": 3, "meta": {"image": "a.png", "size": {"w": 1, "h": 1}}})"),
              "render::SpriteSheet: bad.json: frames: expected an object (hash format) or an array "
              "(array "
              "format), got number 3");
    EXPECT_EQ(
        errorOf(R"({"frames": {}, "meta": {"image": 7, "size": {"w": 1, "h": 1}}})"),
        "render::SpriteSheet: bad.json: meta.image: expected a non-empty string, got number 7");
    EXPECT_EQ(errorOf(R"({"frames": {}, "meta": {"image": "a", "size": {"w": "1", "h": 1}}})"),
              "render::SpriteSheet: bad.json: meta.size.w: expected an integer, got string \"1\"");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 2.5, "h": 4}})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame.w: expected an integer, got "
              "number 2.5");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": -1, "y": 0, "w": 2, "h": 4}})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame.x: expected an integer in [0, "
              "1048576], got "
              "number -1");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 0, "h": 4}})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame.w: expected an integer in [1, "
              "1048576], got "
              "number 0");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 2, "h": 4}, "rotated": "yes"})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].rotated: expected true or false, got "
              "string \"yes\"");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 2, "h": 4}, "trimmed": 1})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].trimmed: expected true or false, got "
              "number 1");
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": [0, 0, 2, 4]})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame: expected an object, got array "
              "[0,0,2,4]");
    EXPECT_EQ(
        errorOf(oneFrame(
            R"({"frame": {"x": 0, "y": 0, "w": 2, "h": 4}, "pivot": {"x": null, "y": 0}})")),
        "render::SpriteSheet: bad.json: frames[\"a\"].pivot.x: expected a number, got null null");
    EXPECT_EQ(
        errorOf(
            R"({"frames": [{"filename": 5, "frame": {"x": 0, "y": 0, "w": 1, "h": 1}}], "meta": {"image": "a", "size": {"w": 1, "h": 1}}})"),
        "render::SpriteSheet: bad.json: frames[0].filename: expected a string, got number 5");
    EXPECT_EQ(errorOf(R"({"frames": [17], "meta": {"image": "a", "size": {"w": 1, "h": 1}}})"),
              "render::SpriteSheet: bad.json: frames[0]: expected an object, got number 17");
}

TEST(SpriteSheet, AFrameOutsideTheImageIsAnError) {
    // 60 + 8 > 64 wide.
    EXPECT_EQ(errorOf(oneFrame(R"({"frame": {"x": 60, "y": 0, "w": 8, "h": 4}})")),
              "render::SpriteSheet: bad.json: frames[\"a\"].frame: frame \"a\" (x 60, y 0, w 8, h "
              "4) lies outside "
              "the 64x64 image (meta.size)");
    // Displayed 8x40 at (0, 30): fits unrotated only if 30 + 40 <= 64, which it does not; rotated it is
    // stored 40 wide and 8 tall, which fits.
    EXPECT_THAT(errorOf(oneFrame(R"({"frame": {"x": 0, "y": 30, "w": 8, "h": 40}})")),
                HasSubstr("lies outside"));
    EXPECT_NO_THROW(static_cast<void>(SpriteSheet::fromString(
        oneFrame(R"({"frame": {"x": 0, "y": 30, "w": 8, "h": 40}, "rotated": true})"), "s")));
    EXPECT_EQ(
        errorOf(oneFrame(R"({"frame": {"x": 30, "y": 0, "w": 8, "h": 40}, "rotated": true})")),
        "render::SpriteSheet: bad.json: frames[\"a\"].frame: frame \"a\" (x 30, y 0, w 40, h 8, "
        "rotated) "
        "lies outside the 64x64 image (meta.size)");
    // A trimmed rectangle outside its source size.
    EXPECT_EQ(
        errorOf(oneFrame(
            R"({"frame": {"x": 0, "y": 0, "w": 8, "h": 8}, "spriteSourceSize": {"x": 4, "y": 0, "w": 8, "h": 8}, "sourceSize": {"w": 10, "h": 8}})")),
        "render::SpriteSheet: bad.json: frames[\"a\"].spriteSourceSize: rectangle (x 4, y 0, w 8, "
        "h 8) lies "
        "outside sourceSize 10x8");
}

TEST(SpriteSheet, TheLoadedImageMustHoldEveryFrame) {
    const SpriteSheet sheet = SpriteSheet::fromString(kHash, "hero.json", "assets");
    EXPECT_NO_THROW(sheet.checkImageSize({128, 64}));
    EXPECT_NO_THROW(sheet.checkImageSize({256, 256}));
    try {
        sheet.checkImageSize({64, 64});
        FAIL() << "no error";
    } catch (const Error& e) {
        // jump.png (32..52) still fits in 64; fall.png (64..74) does not.
        EXPECT_EQ(std::string(e.what()),
                  "render::SpriteSheet: hero.json: frames[\"fall.png\"].frame: frame \"fall.png\" "
                  "(x 64, y 0, w 10, "
                  "h 40, rotated) lies outside the 64x64 image loaded from '" +
                      (std::filesystem::path("assets") / "hero.png").string() +
                      "' (meta.size says 128x64)");
    }
}

TEST(SpriteSheet, DuplicateNamesInTheArrayFormatAreAnError) {
    EXPECT_EQ(errorOf(R"({"frames": [{"filename": "a", "frame": {"x": 0, "y": 0, "w": 1, "h": 1}},
                                     {"filename": "a", "frame": {"x": 0, "y": 0, "w": 1, "h": 1}}],
                         "meta": {"image": "a", "size": {"w": 1, "h": 1}}})"),
              "render::SpriteSheet: bad.json: frames[1]: duplicate frame name \"a\"");
}

TEST(SpriteSheet, HugeAndOddNumbersAreRejectedNotWrapped) {
    EXPECT_THAT(
        errorOf(oneFrame(R"({"frame": {"x": 18446744073709551615, "y": 0, "w": 1, "h": 1}})")),
        HasSubstr("frames[\"a\"].frame.x: expected an integer in [0, 1048576]"));
    EXPECT_THAT(errorOf(oneFrame(R"({"frame": {"x": 1e300, "y": 0, "w": 1, "h": 1}})")),
                HasSubstr("frames[\"a\"].frame.x: expected an integer"));
    EXPECT_THAT(
        errorOf(oneFrame(
            R"({"frame": {"x": 0, "y": 0, "w": 1, "h": 1}, "pivot": {"x": 1e300, "y": 0}})")),
        HasSubstr("frames[\"a\"].pivot.x: expected a number in [-1e6, 1e6]"));
    // Whole numbers written with a fraction are fine.
    EXPECT_NO_THROW(static_cast<void>(SpriteSheet::fromString(
        oneFrame(R"({"frame": {"x": 2.0, "y": 0, "w": 1, "h": 1}})"), "s")));
}

TEST(SpriteSheet, DeepNestingIsRefusedBeforeParsingNamingTheFileAndDepth) {
    // 100 000 levels used to overflow the stack: in an ignored key (ordered_json copied the
    // value), as the whole document (describe() printed it), and cut off mid-file.
    const int n = 100000;
    const std::string deep = std::string(n, '[') + std::string(n, ']');
    const auto dir = std::filesystem::temp_directory_path() / "e2d_sheet_deep_test";
    std::filesystem::create_directories(dir);
    const auto path = dir / "d.json";
    std::ofstream(path) << deep;
    try {
        static_cast<void>(SpriteSheet::fromFile(path));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "render::SpriteSheet: " + path.string() +
                      ":1:257: arrays and objects nest deeper than 256 levels; a sheet needs 4");
    }
    EXPECT_THAT(
        errorOf(oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 1, "h": 1}, "extra": )" + deep + "}")),
        HasSubstr(":1:324: arrays and objects nest deeper than 256 levels"));
    EXPECT_THAT(errorOf(deep.substr(0, n / 2 + 7)), HasSubstr("nest deeper than 256 levels"));
    // Brackets in strings are text, and 256 levels are allowed (3 hold the frame).
    const std::string allowed = std::string(253, '[') + std::string(253, ']');
    EXPECT_NO_THROW(static_cast<void>(SpriteSheet::fromString(
        oneFrame(R"({"frame": {"x": 0, "y": 0, "w": 1, "h": 1}, "extra": )" + allowed +
                 R"(, "s": "[[[[[["})"),
        "s")));
}

TEST(SpriteSheet, ADirectoryIsNamedAsOne) {
    const auto dir = std::filesystem::temp_directory_path() / "e2d_sheet_dir_test.json";
    std::filesystem::create_directories(dir);
    try {
        static_cast<void>(SpriteSheet::fromFile(dir));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "render::SpriteSheet: " + dir.string() +
                                             ": cannot read the file (it is a directory)");
    }
}

TEST(SpriteSheet, BytesQuotedFromTheFileAreEscapedWhenNotPrintable) {
    // An ill-formed UTF-8 string and a control character: nlohmann quotes what it read.
    const std::string message = errorOf("{\"frames\": \"\xFF\xFE\"}", "bin.json");
    EXPECT_THAT(message,
                testing::StartsWith("render::SpriteSheet: bin.json:1:13: malformed JSON: "));
    EXPECT_THAT(message, HasSubstr("\\xff"));
    EXPECT_EQ(message.find('\xFF'), std::string::npos) << message;
    // A raw control character: nlohmann names it itself, and the message holds no such byte.
    EXPECT_EQ(errorOf("{\"a\x01\": 1}").find('\x01'), std::string::npos);
    // A frame name holding a control character (written as a JSON escape) is escaped when named.
    EXPECT_EQ(
        errorOf(R"({"frames": [{"filename": "x\u0007", "frame": {"x": 0, "y": 0, "w": 1, "h": 1}},
                                     {"filename": "x\u0007", "frame": {"x": 0, "y": 0, "w": 1, "h": 1}}],
                         "meta": {"image": "a", "size": {"w": 1, "h": 1}}})"),
        "render::SpriteSheet: bad.json: frames[1]: duplicate frame name \"x\\x07\"");
}
