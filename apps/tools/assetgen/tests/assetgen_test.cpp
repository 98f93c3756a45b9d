// SPDX-License-Identifier: MIT
// The asset generator's painting, packing and sound code, checked from first principles and
// read back through the libraries that load the assets (render::SpriteSheet, loadImage,
// libsndfile).
#include "canvas.hpp"
#include "sheet.hpp"
#include "sound.hpp"

#include <e2d/core/error.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <numbers>

namespace e2d::assetgen {
namespace {

std::filesystem::path tempFolder(const std::string& name) {
    auto folder = std::filesystem::temp_directory_path() /
                  ("e2d_assetgen_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

double coveredPixels(const Canvas& c) {
    double sum = 0;
    for (int y = 0; y < c.height(); ++y) {
        for (int x = 0; x < c.width(); ++x) {
            sum += c.pixel(x, y).a / 255.0;
        }
    }
    return sum;
}

TEST(Canvas, CircleCoversPiRSquaredAndIsCentred) {
    Canvas c(64, 64);
    c.fillCircle(32, 32, 20, {255, 0, 0, 255});
    EXPECT_NEAR(coveredPixels(c), std::numbers::pi * 20 * 20, 0.01 * std::numbers::pi * 400);
    EXPECT_EQ(c.pixel(32, 32), (Colour{255, 0, 0, 255}));
    EXPECT_EQ(c.pixel(32, 10).a, 0); // 22 px above the centre
    EXPECT_EQ(c.pixel(32, 13).a, 255);
    // Symmetric about the centre.
    for (int d = 0; d < 25; ++d) {
        EXPECT_EQ(c.pixel(32 + d, 32).a, c.pixel(31 - d, 32).a) << d;
    }
}

TEST(Canvas, RingAndRoundedRectAreas) {
    Canvas ring(64, 64);
    ring.strokeCircle(32, 32, 20, 4, {0, 0, 255, 255});
    EXPECT_NEAR(coveredPixels(ring), std::numbers::pi * (22 * 22 - 18 * 18), 8.0);
    EXPECT_EQ(ring.pixel(32, 32).a, 0);

    Canvas rect(64, 64);
    rect.fillRoundedRect(10, 10, 40, 30, 5, {0, 255, 0, 255});
    // A 40 x 30 rectangle less four corners of (r^2 - pi r^2 / 4).
    EXPECT_NEAR(coveredPixels(rect), 40 * 30 - (4 - std::numbers::pi) * 25, 2.0);
    EXPECT_EQ(rect.pixel(10, 10).a, 0);   // cut corner
    EXPECT_EQ(rect.pixel(30, 10).a, 255); // top edge
    EXPECT_EQ(rect.pixel(9, 20).a, 0);

    Canvas outline(64, 64);
    outline.strokeRoundedRect(10, 10, 40, 30, 0, 2, {0, 255, 0, 255});
    EXPECT_NEAR(coveredPixels(outline), 40 * 30 - 36 * 26, 2.0);
}

TEST(Canvas, GradientsGoFromOneColourToTheOther) {
    Canvas c(16, 11);
    c.linearGradient(0, 0, 16, 11, {0, 0, 0, 255}, {200, 100, 50, 255});
    EXPECT_EQ(c.pixel(3, 0), (Colour{0, 0, 0, 255}));
    EXPECT_EQ(c.pixel(3, 10), (Colour{200, 100, 50, 255}));
    EXPECT_EQ(c.pixel(3, 5), (Colour{100, 50, 25, 255}));
    Canvas h(11, 4);
    h.linearGradient(0, 0, 11, 4, {0, 0, 0, 255}, {100, 0, 0, 255}, false);
    EXPECT_EQ(h.pixel(5, 2).r, 50);

    Canvas r(64, 64);
    r.radialGradient(32, 32, 30, {255, 255, 255, 255}, {0, 0, 0, 255});
    // Pixel centres (32.5, 32.5) and (32.5, 4.5) lie 0.71 and 27.5 px from the centre.
    EXPECT_NEAR(r.pixel(32, 32).r, 255 * (1 - std::sqrt(0.5) / 30), 1);
    EXPECT_NEAR(r.pixel(32, 4).r, 255 * (1 - 27.5 / 30), 1);
}

TEST(Canvas, BlendsSourceOver) {
    Canvas c(4, 4, {0, 0, 255, 255});
    c.fillRect(0, 0, 4, 4, {255, 0, 0, 128});
    EXPECT_EQ(c.pixel(1, 1), (Colour{128, 0, 127, 255}));
    Canvas clear(4, 4);
    clear.fillRect(0, 0, 4, 4, {255, 0, 0, 128});
    EXPECT_EQ(clear.pixel(1, 1), (Colour{255, 0, 0, 128})); // straight alpha kept
}

TEST(Canvas, TriangleAndLine) {
    Canvas c(40, 40);
    c.fillTriangle(0, 0, 40, 0, 0, 40, {255, 255, 255, 255});
    EXPECT_NEAR(coveredPixels(c), 800, 25.0);
    EXPECT_EQ(c.pixel(5, 5).a, 255);
    EXPECT_EQ(c.pixel(35, 35).a, 0);
    Canvas l(40, 40);
    l.line(5, 20, 35, 20, 4, {255, 255, 255, 255});
    EXPECT_NEAR(coveredPixels(l), 30 * 4 + std::numbers::pi * 4, 3.0);
}

TEST(Canvas, BadSizeAndPixelOutsideAreErrors) {
    EXPECT_THAT([] { Canvas c(0, 5); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("got 0 x 5")));
    Canvas c(4, 4);
    EXPECT_THAT([&] { (void)c.pixel(4, 0); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("(4, 0) is outside")));
}

SheetFrame solidFrame(const std::string& name, int w, int h, Colour colour) {
    Canvas c(w, h, colour);
    return {name, c};
}

TEST(Sheet, PackedFramesDoNotOverlapAndStayInside) {
    std::vector<SheetFrame> frames;
    for (int i = 0; i < 30; ++i) {
        frames.push_back(solidFrame("f" + std::to_string(i), 10 + (i * 7) % 23, 8 + (i * 5) % 17,
                                    {255, 0, 0, 255}));
    }
    const SheetLayout layout = packFrames(frames, 100, 1);
    ASSERT_EQ(layout.frames.size(), frames.size());
    EXPECT_LE(layout.width, 100);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const PackedFrame& a = layout.frames[i];
        EXPECT_EQ(a.w, frames[i].image.width());
        EXPECT_EQ(a.h, frames[i].image.height());
        EXPECT_GE(a.x, 1);
        EXPECT_GE(a.y, 1);
        EXPECT_LE(a.x + a.w + 1, layout.width);
        EXPECT_LE(a.y + a.h + 1, layout.height);
        for (std::size_t j = i + 1; j < frames.size(); ++j) {
            const PackedFrame& b = layout.frames[j];
            // At least one pixel of padding each: two apart.
            const bool apart = a.x + a.w + 2 <= b.x || b.x + b.w + 2 <= a.x ||
                               a.y + a.h + 2 <= b.y || b.y + b.h + 2 <= a.y;
            EXPECT_TRUE(apart) << i << " and " << j;
        }
    }
}

TEST(Sheet, WrittenSheetReadsBackThroughSpriteSheet) {
    const auto folder = tempFolder("sheet");
    std::vector<SheetFrame> frames = {solidFrame("run1.png", 12, 20, {255, 0, 0, 255}),
                                      solidFrame("run2.png", 16, 10, {0, 255, 0, 255}),
                                      solidFrame("run10.png", 30, 30, {0, 0, 255, 255})};
    writeSheet(frames, folder, "hero", 64);
    const render::SpriteSheet sheet = render::SpriteSheet::fromFile(folder / "hero.json");
    EXPECT_EQ(sheet.imagePath(), folder / "hero.png");
    const render::Image image = render::loadImage(sheet.imagePath());
    EXPECT_EQ(sheet.imageSize(), glm::ivec2(image.width, image.height));
    sheet.checkImageSize({image.width, image.height});
    ASSERT_EQ(sheet.frames().size(), 3u);
    EXPECT_EQ(sheet.frames()[0].name, "run1.png"); // file order is the order given
    EXPECT_EQ(sheet.animationFrames("run"), (std::vector<int>{0, 1, 2}));
    for (const SheetFrame& f : frames) {
        const render::SpriteFrame& sf = sheet.frame(f.name);
        EXPECT_EQ(sf.size(), glm::ivec2(f.image.width(), f.image.height()));
        const Colour want = f.image.pixel(0, 0);
        for (int y = 0; y < sf.region.h; ++y) {
            for (int x = 0; x < sf.region.w; ++x) {
                const std::uint8_t* p = image.at(sf.region.x + x, sf.region.y + y);
                ASSERT_EQ((Colour{p[0], p[1], p[2], p[3]}), want) << f.name << " " << x << "," << y;
            }
        }
        // The padding pixel left of the frame is transparent.
        EXPECT_EQ(image.at(sf.region.x - 1, sf.region.y)[3], 0);
    }
    std::filesystem::remove_all(folder);
}

TEST(Sheet, DuplicateNamesAndWideFramesAreErrors) {
    std::vector<SheetFrame> dup = {solidFrame("a", 4, 4, {}), solidFrame("a", 4, 4, {})};
    EXPECT_THAT(
        [&] { (void)packFrames(dup); },
        testing::ThrowsMessage<core::Error>(testing::HasSubstr("two frames are called 'a'")));
    std::vector<SheetFrame> wide = {solidFrame("w", 100, 4, {})};
    EXPECT_THAT([&] { (void)packFrames(wide, 64); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("'w' is 100 pixels wide")));
}

int zeroCrossingsUp(const Sound& s) {
    int n = 0;
    for (std::size_t i = 1; i < s.samples.size(); ++i) {
        n += s.samples[i - 1] < 0 && s.samples[i] >= 0;
    }
    return n;
}

double rms(const std::vector<float>& v) {
    double sum = 0;
    for (float x : v) {
        sum += static_cast<double>(x) * x;
    }
    return std::sqrt(sum / static_cast<double>(v.size()));
}

TEST(Sound, ToneHasItsFrequencyAndLevel) {
    const Sound s = tone(Wave::Sine, 440, 1.0, 0.5);
    EXPECT_EQ(s.samples.size(), 44100u);
    EXPECT_NEAR(zeroCrossingsUp(s), 440, 1);
    EXPECT_NEAR(rms(s.samples), 0.5 / std::sqrt(2.0), 1e-3);
    const Sound sq = tone(Wave::Square, 100, 1.0, 0.25);
    EXPECT_NEAR(rms(sq.samples), 0.25, 1e-3);
    // A glide from 200 to 600 Hz averages 400 cycles a second.
    EXPECT_NEAR(zeroCrossingsUp(tone(Wave::Sine, 200, 1.0, 0.5, 600)), 400, 2);
    EXPECT_NEAR(noteFrequency(69), 440.0, 1e-9);
    EXPECT_NEAR(noteFrequency(81), 880.0, 1e-9);
}

TEST(Sound, EnvelopeStartsAndEndsAtZero) {
    Sound s = tone(Wave::Square, 200, 0.5, 1.0);
    shape(s, {0.01, 0.05, 0.5, 0.1});
    EXPECT_EQ(s.samples.front(), 0.0f);
    EXPECT_NEAR(s.samples.back(), 0.0f, 1e-3);
    // Sustain level in the middle.
    EXPECT_NEAR(std::abs(s.samples[s.samples.size() / 2]), 0.5f, 1e-6);
}

TEST(Sound, SequenceLastsItsBeatsAndNoiseIsReproducible) {
    const Sound seq = sequence({{60, 1}, {-1, 1}, {64, 2}}, 120, Wave::Sine, {}, 0.3);
    EXPECT_EQ(seq.samples.size(), 88200u); // 4 beats at 120 bpm = 2 s
    // The rest is silent.
    EXPECT_EQ(rms({seq.samples.begin() + 22050 + 10, seq.samples.begin() + 44100 - 10}), 0.0);
    EXPECT_EQ(noise(0.1, 0.5, 7).samples, noise(0.1, 0.5, 7).samples);
    EXPECT_NE(noise(0.1, 0.5, 7).samples, noise(0.1, 0.5, 8).samples);
    Sound a = silence(1.0);
    EXPECT_THAT([&] { mixInto(a, silence(1.0, 22050), 0); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("44100 and 22050")));
}

TEST(Sound, WrittenFilesReadBackThroughLibsndfile) {
    const auto folder = tempFolder("sound");
    const Sound s = tone(Wave::Sine, 440, 0.5, 0.5);
    for (const char* name : {"a.wav", "a.ogg", "a.flac"}) {
        writeSound(s, folder / name);
        SF_INFO info{};
        SNDFILE* f = sf_open((folder / name).c_str(), SFM_READ, &info);
        ASSERT_NE(f, nullptr) << name;
        EXPECT_EQ(info.channels, 1);
        EXPECT_EQ(info.samplerate, 44100);
        EXPECT_EQ(info.frames, 22050);
        std::vector<float> back(static_cast<std::size_t>(info.frames));
        EXPECT_EQ(sf_readf_float(f, back.data(), info.frames), info.frames);
        sf_close(f);
        EXPECT_NEAR(rms(back), rms(s.samples), 0.01) << name;
    }
    EXPECT_THAT([&] { writeSound(s, folder / "a.mp3"); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("unknown extension")));
    EXPECT_THAT([&] { writeSound(s, folder / "missing" / "a.wav"); },
                testing::ThrowsMessage<core::Error>(testing::HasSubstr("missing/a.wav")));
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace e2d::assetgen
