// SPDX-License-Identifier: MIT
// Assets of apps/platformer: the player's sheet, level props, parallax layers, sounds, music.
#include "asset_set.hpp"
#include "canvas.hpp"
#include "sheet.hpp"
#include "sound.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace e2d::assetgen {
namespace {

constexpr int kPlayerW = 48;
constexpr int kPlayerH = 56;

const Colour kSkin{255, 205, 160, 255};
const Colour kShirt{220, 70, 60, 255};
const Colour kShirtDark{160, 40, 40, 255};
const Colour kTrousers{50, 70, 140, 255};
const Colour kHair{90, 50, 20, 255};
const Colour kOutline{30, 20, 20, 255};

// The hero facing right. `legA`/`legB` swing the legs (radians from straight down), `armA`/
// `armB` the arms, `bob` lifts the body (pixels).
Canvas playerFrame(float legA, float legB, float armA, float armB, float bob) {
    Canvas c(kPlayerW, kPlayerH);
    const float hipX = 24;
    const float hipY = 38 - bob;
    const float shoulderY = 24 - bob;
    auto limb = [&](float x, float y, float angle, float length, float thickness, Colour colour) {
        const float ex = x + length * std::sin(angle);
        const float ey = y + length * std::cos(angle);
        c.line(x, y, ex, ey, thickness + 2, kOutline);
        c.line(x, y, ex, ey, thickness, colour);
        return std::pair{ex, ey};
    };
    // Back limbs first, darker.
    limb(hipX, hipY, legB, 15, 6, mix(kTrousers, kOutline, 0.3));
    limb(hipX, shoulderY + 2, armB, 12, 5, kShirtDark);
    // Body.
    c.fillRoundedRect(15, shoulderY - 2, 18, 18, 6, kOutline);
    c.fillRoundedRect(16, shoulderY - 1, 16, 16, 5, kShirt);
    // Head with hair and an eye looking right.
    c.fillCircle(25, shoulderY - 10, 10, kOutline);
    c.fillCircle(25, shoulderY - 10, 9, kSkin);
    c.fillRoundedRect(15, shoulderY - 21, 18, 8, 4, kHair);
    c.fillCircle(30, shoulderY - 10, 2, kOutline);
    // Front limbs.
    limb(hipX, hipY, legA, 15, 6, kTrousers);
    limb(hipX, shoulderY + 2, armA, 12, 5, kShirt);
    return c;
}

void playerSheet(const std::filesystem::path& folder) {
    std::vector<SheetFrame> frames;
    constexpr float kPi = std::numbers::pi_v<float>;
    for (int i = 0; i < 4; ++i) { // idle: breathing
        const float bob = i == 1 || i == 2 ? 1.0f : 0.0f;
        frames.push_back({"idle" + std::to_string(i + 1) + ".png",
                          playerFrame(0.08f, -0.08f, 0.15f, -0.15f, bob)});
    }
    for (int i = 0; i < 6; ++i) { // run: legs and arms swinging opposite
        const float s = std::sin(2.0f * kPi * static_cast<float>(i) / 6.0f);
        const float bob = std::abs(s) * 2.0f;
        frames.push_back({"run" + std::to_string(i + 1) + ".png",
                          playerFrame(0.8f * s, -0.8f * s, -0.9f * s, 0.9f * s, bob)});
    }
    frames.push_back({"jump1.png", playerFrame(0.6f, -0.3f, 2.4f, 2.0f, 2.0f)});
    frames.push_back({"fall1.png", playerFrame(0.3f, -0.5f, 1.6f, -1.6f, 0.0f)});
    writeSheet(frames, folder, "player", 256);
}

void props(const std::filesystem::path& folder) {
    // A grass tile (1 x 0.5 m at 48 px/m) with blades along the top edge.
    Canvas grass(48, 24, {110, 72, 44, 255});
    grass.fillRect(0, 0, 48, 12, {70, 170, 60, 255});
    grass.fillRect(0, 9, 48, 3, {50, 130, 45, 255});
    for (int i = 0; i < 8; ++i) {
        const float x = 3.0f + 6.0f * static_cast<float>(i);
        grass.fillTriangle(x - 3, 2, x + 3, 2, x, 0, {100, 200, 80, 255});
    }
    grass.fillCircle(12, 18, 2, {90, 60, 36, 255});
    grass.fillCircle(36, 20, 2.5f, {130, 90, 55, 255});
    grass.writePng(folder / "grass.png");

    // Spikes: three grey teeth on a dark base (1 x 0.8 m).
    Canvas spikes(48, 38);
    spikes.fillRect(0, 30, 48, 8, {60, 60, 70, 255});
    for (int i = 0; i < 3; ++i) {
        const float x = 16.0f * static_cast<float>(i);
        spikes.fillTriangle(x, 31, x + 16, 31, x + 8, 2, {40, 40, 48, 255});
        spikes.fillTriangle(x + 2, 30, x + 14, 30, x + 8, 6, {200, 205, 215, 255});
        spikes.fillTriangle(x + 8, 6, x + 14, 30, x + 9, 30, {150, 155, 170, 255});
    }
    spikes.writePng(folder / "spikes.png");

    // A plank of the one-way platform (1 x 0.3 m).
    Canvas plank(48, 14, {120, 80, 40, 255});
    plank.fillRect(0, 0, 48, 4, {170, 120, 70, 255});
    plank.fillRect(0, 11, 48, 3, {80, 50, 25, 255});
    plank.fillCircle(6, 7, 1.5f, {60, 40, 20, 255});
    plank.fillCircle(42, 7, 1.5f, {60, 40, 20, 255});
    plank.writePng(folder / "plank.png");

    // The lift (3 x 0.5 m): a steel slab with yellow and black stripes.
    Canvas lift(144, 24, {90, 95, 110, 255});
    lift.fillRect(0, 0, 144, 5, {170, 175, 190, 255});
    for (int i = 0; i < 10; ++i) {
        const float x = 16.0f * static_cast<float>(i);
        lift.fillTriangle(x, 24, x + 8, 24, x + 16, 8, {240, 200, 40, 255});
        lift.fillTriangle(x + 8, 24, x + 16, 8, x + 24, 8, {30, 30, 30, 255});
    }
    lift.fillRect(0, 5, 144, 3, {60, 60, 70, 255});
    lift.strokeRoundedRect(0, 0, 144, 24, 3, 2, {40, 40, 50, 255});
    lift.writePng(folder / "platform.png");

    // A coin.
    Canvas coin(32, 32);
    coin.fillCircle(16, 16, 15, {150, 100, 10, 255});
    coin.fillCircle(16, 16, 12.5f, {250, 200, 40, 255});
    coin.fillRoundedRect(14, 8, 4, 16, 2, {200, 140, 20, 255});
    coin.fillCircle(11, 10, 2.5f, {255, 245, 200, 255});
    coin.writePng(folder / "coin.png");

    // The goal flag on its pole (1 x 3 m).
    Canvas flag(48, 144);
    flag.fillRect(6, 4, 5, 140, {220, 220, 230, 255});
    flag.fillCircle(8.5f, 5, 4, {250, 210, 60, 255});
    flag.fillTriangle(11, 10, 46, 24, 11, 40, {60, 200, 90, 255});
    flag.fillTriangle(11, 10, 46, 24, 11, 18, {90, 230, 120, 255});
    flag.fillRect(0, 138, 18, 6, {80, 80, 90, 255});
    flag.writePng(folder / "flag.png");
}

void backgrounds(const std::filesystem::path& folder) {
    // Sky: a vertical gradient with a sun and a few clouds (stays put).
    Canvas sky(1280, 720);
    sky.linearGradient(0, 0, 1280, 720, {90, 160, 235, 255}, {200, 230, 250, 255});
    sky.radialGradient(1040, 140, 90, {255, 250, 210, 255}, {255, 240, 170, 0});
    sky.fillCircle(1040, 140, 46, {255, 245, 190, 255});
    const float clouds[][3] = {
        {180, 120, 1.0f}, {520, 200, 0.8f}, {820, 90, 1.2f}, {1180, 260, 0.7f}};
    for (const auto& cl : clouds) {
        const float s = cl[2];
        for (const auto& puff : {std::array{-40.0f, 8.0f, 30.0f}, std::array{0.0f, 0.0f, 40.0f},
                                 std::array{42.0f, 10.0f, 28.0f}}) {
            sky.fillCircle(cl[0] + puff[0] * s, cl[1] + puff[1] * s, puff[2] * s,
                           {255, 255, 255, 230});
        }
    }
    sky.writePng(folder / "sky.png");

    // Far hills (1280 x 360, tiles left to right: the curve is periodic over the width).
    Canvas hills(1280, 360);
    for (int x = 0; x < 1280; ++x) {
        const double u = 2 * std::numbers::pi * x / 1280.0;
        const float top = static_cast<float>(170 - 60 * std::sin(u) - 35 * std::sin(3 * u + 1.0));
        hills.fillRect(static_cast<float>(x), top, 1, 360 - top, {120, 170, 200, 255});
    }
    hills.writePng(folder / "hills.png");

    // Near trees and bushes (1280 x 360, also periodic), transparent above them.
    Canvas trees(1280, 360);
    for (int x = 0; x < 1280; ++x) {
        const double u = 2 * std::numbers::pi * x / 1280.0;
        const float top = static_cast<float>(250 - 25 * std::sin(2 * u) - 15 * std::sin(5 * u));
        trees.fillRect(static_cast<float>(x), top, 1, 360 - top, {60, 130, 90, 255});
    }
    for (int i = 0; i < 9; ++i) {
        const float x = 70.0f + 140.0f * static_cast<float>(i);
        const float h = 90.0f + 30.0f * static_cast<float>(i % 3);
        trees.fillRect(x - 5, 280 - h * 0.5f, 10, h * 0.5f + 20, {90, 70, 50, 255});
        trees.fillCircle(x, 280 - h * 0.6f, h * 0.35f, {45, 110, 70, 255});
        trees.fillCircle(x - 10, 280 - h * 0.7f, h * 0.22f, {70, 150, 90, 255});
    }
    trees.writePng(folder / "trees.png");
}

void sounds(const std::filesystem::path& folder) {
    // Coin: two quick rising square-wave notes.
    Sound coin = silence(0.3);
    Sound a = tone(Wave::Square, noteFrequency(83), 0.07, 0.5);
    Sound b = tone(Wave::Square, noteFrequency(88), 0.2, 0.5);
    shape(a, {0.002, 0.02, 0.8, 0.02});
    shape(b, {0.002, 0.05, 0.6, 0.12});
    mixInto(coin, a, 0.0);
    mixInto(coin, b, 0.07);
    normalise(coin, 0.8);
    writeSound(coin, folder / "coin.wav");

    // Jump: a short upward sweep.
    Sound jump = tone(Wave::Triangle, 300, 0.18, 0.6, 700);
    shape(jump, {0.003, 0.05, 0.6, 0.08});
    normalise(jump, 0.7);
    writeSound(jump, folder / "jump.wav");

    // Hurt: a falling buzz over a puff of noise.
    Sound hurt = tone(Wave::Saw, 400, 0.45, 0.5, 90);
    mixInto(hurt, noise(0.2, 0.4, 7), 0.0);
    shape(hurt, {0.003, 0.1, 0.5, 0.2});
    normalise(hurt, 0.8);
    writeSound(hurt, folder / "hurt.wav");

    // Win: a little arpeggio.
    Sound win = sequence({{72, 0.5}, {76, 0.5}, {79, 0.5}, {84, 1.5}}, 240, Wave::Square,
                         {0.005, 0.05, 0.6, 0.1}, 0.4);
    normalise(win, 0.8);
    writeSound(win, folder / "win.wav");

    // Music: eight bars at 140 bpm, a bouncy tune over a bass line (loops seamlessly; streamed).
    const std::vector<Note> melody = {
        {76, 0.5}, {79, 0.5}, {84, 1},   {83, 0.5}, {79, 0.5}, {76, 1},   {74, 0.5}, {77, 0.5},
        {81, 1},   {79, 0.5}, {77, 0.5}, {74, 1},   {72, 0.5}, {76, 0.5}, {79, 1},   {81, 0.5},
        {79, 0.5}, {76, 1},   {74, 0.5}, {71, 0.5}, {74, 0.5}, {77, 0.5}, {76, 2},   {76, 0.5},
        {79, 0.5}, {84, 1},   {86, 0.5}, {84, 0.5}, {79, 1},   {81, 0.5}, {79, 0.5}, {77, 1},
        {76, 0.5}, {74, 0.5}, {72, 1},   {74, 0.5}, {76, 0.5}, {77, 1},   {79, 0.5}, {81, 0.5},
        {83, 1},   {84, 2},   {-1, 2}};
    const std::vector<Note> bass = {{48, 1}, {55, 1}, {52, 1}, {55, 1}, {50, 1}, {57, 1}, {53, 1},
                                    {57, 1}, {48, 1}, {55, 1}, {52, 1}, {55, 1}, {43, 1}, {50, 1},
                                    {47, 1}, {50, 1}, {48, 1}, {55, 1}, {52, 1}, {55, 1}, {53, 1},
                                    {57, 1}, {50, 1}, {53, 1}, {50, 1}, {55, 1}, {53, 1}, {55, 1},
                                    {48, 1}, {43, 1}, {48, 2}};
    Sound music = sequence(melody, 140, Wave::Square, {0.01, 0.06, 0.5, 0.05}, 0.22);
    mixInto(music, sequence(bass, 140, Wave::Triangle, {0.01, 0.1, 0.8, 0.1}, 0.5), 0);
    normalise(music, 0.8);
    writeSound(music, folder / "music.ogg");
}

void platformer(const std::filesystem::path& folder) {
    playerSheet(folder);
    props(folder);
    backgrounds(folder);
    sounds(folder);
}

} // namespace

void register_platformer(Registry& registry) {
    registry.add({"platformer",
                  "the platformer's player sheet, props, parallax layers, sounds and music",
                  platformer});
}

} // namespace e2d::assetgen
