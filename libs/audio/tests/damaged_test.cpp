// SPDX-License-Identifier: MIT
// Damaged and truncated sound files: one rule for every format, decoded whole and streamed.
// The files are written here with libsndfile and then cut or overwritten.
#include "audio_test_support.hpp"

#include <e2d/audio/sound_data.hpp>
#include <e2d/core/error.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <string>

namespace e2d::audio {
namespace {

using ::testing::HasSubstr;
using namespace test;

constexpr int kRate = 22050;
constexpr double kSeconds = 4.0;

std::filesystem::path oggTone(const std::string& name) {
    return writeSound(name, SF_FORMAT_OGG | SF_FORMAT_VORBIS, 1, kRate,
                      sine(440.0, kSeconds, kRate, 0.5f));
}

// Byte offsets of the Ogg pages ("OggS") of a file.
std::vector<std::size_t> oggPages(const std::vector<char>& bytes) {
    std::vector<std::size_t> pages;
    for (std::size_t i = 0; i + 4 <= bytes.size(); ++i) {
        if (std::memcmp(bytes.data() + i, "OggS", 4) == 0) {
            pages.push_back(i);
        }
    }
    return pages;
}

std::filesystem::path cutCopy(const std::filesystem::path& from, const std::string& name,
                              std::size_t size) {
    auto bytes = readBytes(from);
    bytes.resize(size);
    return writeBytes(name, bytes);
}

// The same bytes with `count` of them from `at` overwritten.
std::filesystem::path damagedCopy(const std::filesystem::path& from, const std::string& name,
                                  std::size_t at, std::size_t count) {
    auto bytes = readBytes(from);
    for (std::size_t i = at; i < at + count && i < bytes.size(); ++i) {
        bytes[i] = '\x5a';
    }
    return writeBytes(name, bytes);
}

void expectRefused(const DecodeResult& result, const std::string& name, const std::string& reason) {
    EXPECT_FALSE(result.ok());
    EXPECT_TRUE(result.data.samples.empty());
    EXPECT_THAT(result.error, HasSubstr(name));
    EXPECT_THAT(result.error, HasSubstr(reason));
}

// libsndfile decodes a cut Ogg file as a shorter sound with no error (cut between two pages, it
// even reports the shorter length as the file's): only the missing end-of-stream page shows it.
// A damaged page makes it report the last page's length (0.37 s of 4 s here), and decode that.
TEST(DamagedOgg, CutFilesAreRefusedWholeAndFromMemory) {
    const auto full = oggTone("full.ogg");
    const auto bytes = readBytes(full);
    const auto pages = oggPages(bytes);
    ASSERT_GE(pages.size(), 4u);
    ASSERT_TRUE(decodeSoundFile(full).ok()) << decodeSoundFile(full).error;
    const auto insidePage = cutCopy(full, "cut_inside.ogg", bytes.size() * 47 / 100);
    expectRefused(decodeSoundFile(insidePage), insidePage.string(),
                  "truncated: the file ends inside Ogg page");
    const auto betweenPages = cutCopy(full, "cut_between.ogg", pages[pages.size() / 2]);
    expectRefused(decodeSoundFile(betweenPages), betweenPages.string(),
                  "truncated: the Ogg stream has no end-of-stream page (the file ends after page " +
                      std::to_string(pages.size() / 2) + ", at byte " +
                      std::to_string(pages[pages.size() / 2]) + ")");
    const auto cut = readBytes(betweenPages);
    expectRefused(decodeSoundMemory(std::as_bytes(std::span(cut)), "cut-in-memory.ogg"),
                  "cut-in-memory.ogg", "end-of-stream");
    // A tag some tool appended after the last page is no damage.
    auto tagged = bytes;
    tagged.insert(tagged.end(), 128, 'T');
    EXPECT_TRUE(decodeSoundMemory(std::as_bytes(std::span(tagged)), "tagged.ogg").ok());
}

TEST(DamagedOgg, ADamagedMiddleIsRefusedWhole) {
    const auto full = oggTone("full_mid.ogg");
    const auto size = readBytes(full).size();
    const auto damaged = damagedCopy(full, "damaged_mid.ogg", size / 2, 200);
    const DecodeResult result = decodeSoundFile(damaged);
    expectRefused(result, damaged.string(), "damaged: Ogg page 3 at byte 3446 fails its checksum");
}

// Damage in the header pages (here the Vorbis comment packet on page 2) is found before
// libsndfile reads the stream: libsndfile 1.2 fails to open it and leaks libvorbis's info block
// each time (the sound loader's fuzzer ran out of memory on such inputs).
TEST(DamagedOgg, DamagedHeaderPagesAreRefusedBeforeLibsndfileOpensThem) {
    const auto full = oggTone("full_head.ogg");
    const auto bytes = readBytes(full);
    const auto pages = oggPages(bytes);
    ASSERT_GE(pages.size(), 3u);
    const std::string reason =
        "damaged: Ogg page 2 at byte " + std::to_string(pages[1]) + " fails its checksum";
    const auto damaged = damagedCopy(full, "damaged_head.ogg", pages[1] + 40, 8);
    expectRefused(decodeSoundFile(damaged), damaged.string(), reason);
    const auto inMemory = readBytes(damaged);
    expectRefused(decodeSoundMemory(std::as_bytes(std::span(inMemory)), "head-in-memory.ogg"),
                  "head-in-memory.ogg", reason);
}

TEST(DamagedStream, CutAndDamagedOggAreRefusedWhenLoadedAsStreams) {
    Rig rig;
    const auto full = oggTone("stream_full.ogg");
    const auto size = readBytes(full).size();
    const auto cut = cutCopy(full, "stream_cut.ogg", size * 47 / 100);
    const auto damaged = damagedCopy(full, "stream_damaged.ogg", size / 2, 200);
    const SoundId a = rig.mixer.load(cut, LoadMode::Stream);
    const SoundId b = rig.mixer.load(damaged, LoadMode::Stream);
    EXPECT_THAT(rig.mixer.soundInfo(a).error,
                HasSubstr("truncated: the file ends inside Ogg page"));
    EXPECT_THAT(rig.mixer.soundInfo(b).error,
                HasSubstr("damaged: Ogg page 3 at byte 3446 fails its checksum"));
    EXPECT_TRUE(rig.mixer.play(a).isNull());
    EXPECT_TRUE(rig.mixer.play(b).isNull());
    EXPECT_EQ(rig.count(core::LogLevel::Error, cut.string()), 1);
    EXPECT_EQ(rig.count(core::LogLevel::Error, damaged.string()), 1);
}

// Damage a format shows only while decoding (FLAC frames after a damaged one) is found while the
// stream plays: it stops there, logged once per sound however many voices meet it.
TEST(DamagedStream, DamageFoundWhilePlayingStopsTheStreamWithOneMessage) {
    Rig rig;
    const auto full = writeSound("stream_full.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, kRate,
                                 sine(440.0, kSeconds, kRate, 0.5f));
    const auto damaged = damagedCopy(full, "stream_damaged.flac", readBytes(full).size() / 2, 2000);
    const SoundId music = rig.mixer.load(damaged, LoadMode::Stream);
    ASSERT_TRUE(rig.mixer.soundInfo(music).ok()) << rig.mixer.soundInfo(music).error;
    const VoiceId a = rig.mixer.play(music);
    const VoiceId b = rig.mixer.play(music);
    ASSERT_FALSE(a.isNull());
    ASSERT_FALSE(b.isNull());
    const auto out = rig.render(kSeconds + 0.5, 0.05);
    EXPECT_EQ(rig.mixer.state(a), VoiceState::Stopped);
    EXPECT_EQ(rig.count(core::LogLevel::Error,
                        "stream stopped: '" + damaged.string() + "': damaged or truncated"),
              1);
    EXPECT_EQ(rig.messages.size(), 1u);
    // It played up to the damage, then nothing.
    EXPECT_GT(rms(out, 0, kRate).left, 0.1);
    EXPECT_EQ(rms(out, out.size() / 2 - 4800, out.size() / 2).left, 0.0);
    // Whole, the same file is refused with the same words.
    expectRefused(decodeSoundFile(damaged), damaged.string(), "damaged or truncated");
}

// The rule is the one WAV and FLAC already followed: the same files cut, whole and streamed.
TEST(DamagedStream, CutWavAndFlacFollowTheSameRule) {
    for (const int format : {SF_FORMAT_WAV | SF_FORMAT_PCM_16, SF_FORMAT_FLAC | SF_FORMAT_PCM_16}) {
        Rig rig;
        const std::string ext = (format & SF_FORMAT_TYPEMASK) == SF_FORMAT_WAV ? ".wav" : ".flac";
        const auto full =
            writeSound("full" + ext, format, 1, kRate, sine(440.0, kSeconds, kRate, 0.5f));
        const auto cut = cutCopy(full, "cut" + ext, readBytes(full).size() / 2);
        expectRefused(decodeSoundFile(cut), cut.string(), "truncated");
        const SoundId stream = rig.mixer.load(cut, LoadMode::Stream);
        if (rig.mixer.soundInfo(stream).ok()) {
            rig.mixer.play(stream);
            rig.render(kSeconds, 0.05);
        }
        EXPECT_EQ(rig.count(core::LogLevel::Error, cut.string()), 1) << ext;
        EXPECT_EQ(rig.count(core::LogLevel::Error, "truncated"), 1) << ext;
    }
}

// Float samples: a float WAV whose bytes were overwritten decodes to values like 4e12, and NaN or
// infinity make the whole mix non-finite. Such data is refused like a truncated file.
std::vector<float> toneWith(float bad, std::size_t at) {
    auto samples = sine(440.0, 1.0, kRate, 0.5f);
    samples[at] = bad;
    return samples;
}

TEST(DamagedFloat, HugeAndNonFiniteSamplesAreRefusedWhole) {
    const float kInf = std::numeric_limits<float>::infinity();
    const float kNan = std::numeric_limits<float>::quiet_NaN();
    const auto huge =
        writeSound("huge.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, kRate, toneWith(4e12f, 11025));
    expectRefused(decodeSoundFile(huge), huge.string(),
                  "damaged: sample 4e+12 at 0.50 s (frame 11025) is beyond +-16");
    const auto nan =
        writeSound("nan.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, kRate, toneWith(kNan, 100));
    expectRefused(decodeSoundFile(nan), nan.string(), "(frame 100) is not finite");
    const auto inf =
        writeSound("inf.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, kRate, toneWith(-kInf, 7));
    expectRefused(decodeSoundFile(inf), inf.string(),
                  "damaged: sample -inf at 0.00 s (frame 7) is not finite");
    // Float files may go a little over full scale: that is not damage.
    const auto hot =
        writeSound("hot.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, kRate, toneWith(1.5f, 11025));
    EXPECT_TRUE(decodeSoundFile(hot).ok()) << decodeSoundFile(hot).error;
    DecodeLimits strict;
    strict.maxSampleMagnitude = 1.0f;
    EXPECT_THAT(decodeSoundFile(hot, strict).error,
                HasSubstr("beyond +-1 (DecodeLimits::maxSampleMagnitude)"));
}

TEST(DamagedFloat, AStreamStopsAtTheDamageAndTheMixStaysFinite) {
    Rig rig;
    const auto path = writeSound("nan_stream.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, kRate,
                                 toneWith(std::numeric_limits<float>::quiet_NaN(), 15000));
    const SoundId sound = rig.mixer.load(path, LoadMode::Stream);
    ASSERT_TRUE(rig.mixer.soundInfo(sound).ok());
    rig.mixer.play(sound);
    const auto out = rig.render(1.2, 0.05);
    for (float s : out) {
        ASSERT_TRUE(std::isfinite(s));
    }
    EXPECT_EQ(rig.count(core::LogLevel::Error,
                        "stream stopped: '" + path.string() + "': damaged: sample nan"),
              1);
}

TEST(DamagedFloat, AddRefusesSamplesThatAreNotFinite) {
    Rig rig;
    SoundData data{1, kRate, toneWith(std::numeric_limits<float>::quiet_NaN(), 3)};
    try {
        rig.mixer.add(std::move(data), "generated");
        FAIL() << "expected core::Error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "audio::Mixer::add(): data.samples[3] must be finite and within +-16 "
                     "(limits.maxSampleMagnitude), got nan");
    }
    MixerDef def;
    def.limits.maxSampleMagnitude = 0.5f;
    EXPECT_THROW(Rig strict(def), core::Error);
}

} // namespace
} // namespace e2d::audio

// Only WAV, Ogg and FLAC reach libsndfile: an MPEG stream (which libsndfile would hand to
// libmpg123, whose resync never returned on one fuzzed input) or any other bytes are refused
// by name, from memory and from a file.
TEST(DamagedFormat, OtherFormatsAreRefusedBeforeLibsndfileSeesThem) {
    const std::string mpeg = std::string("ID3\x03\x00\x00\x00\x00\x00\x00", 10) +
                             std::string("\xff\xfb\x90\x64", 4) + std::string(400, '\x55');
    const auto bytes = std::as_bytes(std::span(mpeg.data(), mpeg.size()));
    const e2d::audio::DecodeResult fromMemory =
        e2d::audio::decodeSoundMemory(bytes, "song.mp3", e2d::audio::DecodeLimits{});
    EXPECT_FALSE(fromMemory.ok());
    EXPECT_NE(fromMemory.error.find("'song.mp3': not a WAV, Ogg or FLAC file"), std::string::npos)
        << fromMemory.error;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "e2d_damaged_format_test.mp3";
    {
        std::ofstream file(path, std::ios::binary);
        file.write(mpeg.data(), static_cast<std::streamsize>(mpeg.size()));
    }
    const e2d::audio::DecodeResult fromFile =
        e2d::audio::decodeSoundFile(path, e2d::audio::DecodeLimits{});
    std::filesystem::remove(path);
    EXPECT_FALSE(fromFile.ok());
    EXPECT_NE(fromFile.error.find("not a WAV, Ogg or FLAC file"), std::string::npos)
        << fromFile.error;
}

namespace e2d::audio {
namespace {

using namespace test;

// A mono 16-bit WAV of 16 frames whose list chunk `list` (after the samples, where most writers
// put it) holds one entry with id `entry` and size `entrySize`, and `tail` bytes after it.
std::vector<char> wavWithListEntry(std::string_view list, std::string_view entry,
                                   std::uint32_t entrySize, std::size_t tail) {
    std::vector<char> bytes;
    auto put = [&bytes](std::string_view text) {
        bytes.insert(bytes.end(), text.begin(), text.end());
    };
    auto put32 = [&bytes](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) {
            bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
        }
    };
    auto put16 = [&bytes](std::uint16_t v) {
        bytes.push_back(static_cast<char>(v & 0xffu));
        bytes.push_back(static_cast<char>(v >> 8));
    };
    put("RIFF");
    put32(0); // set below
    put("WAVEfmt ");
    put32(16);
    put16(1);     // PCM
    put16(1);     // channels
    put32(8000);  // frames per second
    put32(16000); // bytes per second
    put16(2);     // bytes per frame
    put16(16);    // bits per sample
    put("data");
    put32(32);
    for (int i = 0; i < 16; ++i) {
        put16(static_cast<std::uint16_t>(i * 1000));
    }
    put(list);
    put32(static_cast<std::uint32_t>(4 + 8 + tail));
    put("INFO");
    put(entry);
    put32(entrySize);
    bytes.insert(bytes.end(), tail, '\0');
    const auto riffSize = static_cast<std::uint32_t>(bytes.size() - 8);
    for (int i = 0; i < 4; ++i) {
        bytes[4 + static_cast<std::size_t>(i)] = static_cast<char>((riffSize >> (8 * i)) & 0xffu);
    }
    return bytes;
}

// libsndfile 1.2 steps over a list entry by its size as a signed 32-bit number: a size of
// 0xfffffff8 takes it back to the entry's own id, and sf_open() never returns (the sound
// loader's fuzzer found such 133-byte files, in a LIST chunk and in a top-level INFO chunk,
// which libsndfile also reads as a list). The chunks are walked first and the file is refused
// by name, from memory and from a file; the same file with a sane entry loads.
TEST(DamagedWav, AListEntryOf2GiBOrMoreIsRefusedBeforeLibsndfileLoopsOnIt) {
    for (const std::string_view list : {"LIST", "INFO"}) {
        SCOPED_TRACE(list);
        const std::vector<char> looping = wavWithListEntry(list, "abcd", 0xfffffff8u, 16);
        const std::string reason = "damaged: entry 'abcd' at byte 88 (in the list chunk at byte "
                                   "76) claims 4294967288 bytes; the file has " +
                                   std::to_string(looping.size());
        const auto path = writeBytes("list_entry_loop.wav", looping);
        expectRefused(decodeSoundFile(path), path.string(), reason);
        expectRefused(decodeSoundMemory(std::as_bytes(std::span(looping)), "loop-in-memory.wav"),
                      "loop-in-memory.wav", reason);
        // A list that claims 0xffffffff bytes is read to the end of the file all the same.
        std::vector<char> endless = looping;
        std::fill_n(endless.begin() + 80, 4, '\xff');
        expectRefused(decodeSoundMemory(std::as_bytes(std::span(endless)), "endless.wav"),
                      "endless.wav", reason);

        const std::vector<char> sane = wavWithListEntry(list, "INAM", 16, 16);
        const DecodeResult loaded =
            decodeSoundMemory(std::as_bytes(std::span(sane)), "sane-in-memory.wav");
        ASSERT_TRUE(loaded.ok()) << loaded.error;
        EXPECT_EQ(loaded.data.frames(), 16);
    }
}

} // namespace
} // namespace e2d::audio
