// SPDX-License-Identifier: MIT
// Assets of the seed's demos (apps/sprites, apps/parallax, apps/audio_spatial, apps/audio_listener).
#include "asset_set.hpp"
#include "canvas.hpp"
#include "sheet.hpp"
#include "sound.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace e2d::assetgen {
namespace {

constexpr int kFrames = 8;
constexpr int kCell = 32;

// A gold coin turning about its vertical axis: its visible width follows |cos|.
Canvas coinFrame(int i) {
    Canvas c(kCell, kCell);
    const double angle = 2 * std::numbers::pi * i / kFrames;
    const float w = std::max(4.0f, 26.0f * static_cast<float>(std::abs(std::cos(angle))));
    const float x = (kCell - w) / 2;
    c.fillRoundedRect(x, 3, w, 26, w / 2, {150, 100, 10, 255});
    c.fillRoundedRect(x + 2, 5, w - 4, 22, (w - 4) / 2, {250, 200, 40, 255});
    if (w > 12) {
        c.fillRoundedRect(kCell / 2.0f - 2, 9, 4, 14, 2, {200, 140, 20, 255});
    }
    return c;
}

// A green slime squashing and stretching as it hops.
Canvas slimeFrame(int i) {
    Canvas c(kCell, kCell);
    const double phase = 2 * std::numbers::pi * i / kFrames;
    const float stretch = static_cast<float>(std::sin(phase));
    const float h = 20 + 6 * stretch;
    const float w = 26 - 5 * stretch;
    const float x = (kCell - w) / 2;
    const float y = kCell - 2 - h;
    c.fillRoundedRect(x, y, w, h, std::min(w, h) * 0.45f, {30, 120, 40, 255});
    c.fillRoundedRect(x + 2, y + 2, w - 4, h - 4, std::min(w, h) * 0.4f, {70, 200, 80, 255});
    c.fillCircle(x + w * 0.32f, y + h * 0.38f, 3, {255, 255, 255, 255});
    c.fillCircle(x + w * 0.68f, y + h * 0.38f, 3, {255, 255, 255, 255});
    c.fillCircle(x + w * 0.34f, y + h * 0.40f, 1.5f, {20, 20, 20, 255});
    c.fillCircle(x + w * 0.70f, y + h * 0.40f, 1.5f, {20, 20, 20, 255});
    return c;
}

void sprites(const std::filesystem::path& folder) {
    std::vector<SheetFrame> frames;
    for (int i = 0; i < kFrames; ++i) {
        frames.push_back({"coin" + std::to_string(i + 1) + ".png", coinFrame(i)});
    }
    for (int i = 0; i < kFrames; ++i) {
        frames.push_back({"slime" + std::to_string(i + 1) + ".png", slimeFrame(i)});
    }
    writeSheet(frames, folder, "creatures", 256);
}

void parallax(const std::filesystem::path& folder) {
    // White, so the demo tints each layer; a soft rim reads well when circles overlap.
    Canvas circle(128, 128);
    circle.radialGradient(64, 64, 62, {255, 255, 255, 255}, {255, 255, 255, 150});
    circle.strokeCircle(64, 64, 60, 3, {255, 255, 255, 255});
    circle.writePng(folder / "circle.png");
}

void audio(const std::filesystem::path& folder) {
    // Four short beeps a second: a clear, steady cue for attenuation and panning (2 s loop).
    Sound beeps = silence(2.0);
    for (int i = 0; i < 8; ++i) {
        Sound b = tone(Wave::Triangle, 660, 0.12, 0.8);
        shape(b, {0.005, 0.03, 0.6, 0.06});
        mixInto(beeps, b, i * 0.25);
    }
    normalise(beeps, 0.9);
    writeSound(beeps, folder / "beeps.wav");

    // A four-bar tune over a bass line at 120 bpm (8 s, loops seamlessly).
    const std::vector<Note> melody = {{72, 1},   {76, 1},   {79, 1}, {76, 1}, {74, 1}, {77, 1},
                                      {81, 1},   {77, 1},   {76, 1}, {79, 1}, {84, 1}, {79, 1},
                                      {77, 0.5}, {76, 0.5}, {74, 1}, {72, 2}};
    const std::vector<Note> bass = {{48, 4}, {50, 4}, {52, 4}, {43, 4}};
    Sound tune = sequence(melody, 120, Wave::Square, {0.01, 0.08, 0.5, 0.08}, 0.25);
    mixInto(tune, sequence(bass, 120, Wave::Triangle, {0.02, 0.2, 0.8, 0.2}, 0.5), 0);
    normalise(tune, 0.8);
    writeSound(tune, folder / "tune.ogg");
}

} // namespace

void register_demos(Registry& registry) {
    registry.add({"sprites", "coin and slime animations in one TexturePacker sheet", sprites});
    registry.add({"parallax", "a white soft circle for tinted translucent layers", parallax});
    registry.add({"audio", "a looping beep and a looping tune for the spatial audio demos", audio});
}

} // namespace e2d::assetgen
