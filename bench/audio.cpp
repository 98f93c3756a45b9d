// SPDX-License-Identifier: MIT
// e2d::audio costs: the per-frame update of many moving spatial voices, OpenAL Soft's loopback
// mix of 64 voices, and decoding through the streaming path (chunks of 0.1 s, as a playing
// stream reads them) against a whole-file load, for Ogg/Vorbis and FLAC.
//
// The loopback device needs no sound card; ALSOFT_DRIVERS=null keeps OpenAL Soft from probing
// PulseAudio (set here unless the caller set it).
#include "sound_decoder.hpp" // the streaming path's decoder (private to the library)

#include <e2d/audio/mixer.hpp>
#include <e2d/core/log.hpp>

#include <benchmark/benchmark.h>
#include <sndfile.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

namespace au = e2d::audio;

constexpr int kRate = 48000;

std::filesystem::path benchDir() {
    auto dir =
        std::filesystem::temp_directory_path() / ("e2d_bench_audio_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// Music-like test content: a few partials with a slow tremolo and a little noise, so the lossy
// and lossless encoders have real work (a pure tone compresses to nearly nothing).
std::vector<float> music(double seconds, int rate, int channels) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> noise(-0.02f, 0.02f);
    const auto frames = static_cast<std::size_t>(seconds * rate);
    std::vector<float> samples(frames * static_cast<std::size_t>(channels));
    for (std::size_t i = 0; i < frames; ++i) {
        const double t = static_cast<double>(i) / rate;
        const double tremolo = 0.6 + 0.4 * std::sin(2.0 * std::numbers::pi * 0.5 * t);
        for (int c = 0; c < channels; ++c) {
            double v = 0.0;
            for (int k = 1; k <= 5; ++k) {
                v += std::sin(2.0 * std::numbers::pi * (110.0 * k + 3.0 * c) * t) / (k + 1);
            }
            samples[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] =
                static_cast<float>(0.3 * tremolo * v) + noise(random);
        }
    }
    return samples;
}

std::filesystem::path writeFile(const std::string& name, int format, double seconds) {
    const auto path = benchDir() / name;
    if (std::filesystem::exists(path)) {
        return path;
    }
    const int channels = 2;
    const int rate = 44100;
    const auto samples = music(seconds, rate, channels);
    SF_INFO info{};
    info.channels = channels;
    info.samplerate = rate;
    info.format = format;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    sf_writef_float(file, samples.data(), static_cast<sf_count_t>(samples.size() / channels));
    sf_close(file);
    return path;
}

au::MixerDef loopbackDef(e2d::core::Logger& logger, int voices) {
    au::MixerDef def;
    def.output = au::Output::Loopback;
    def.loopbackSampleRate = kRate;
    def.voiceCount = voices;
    def.logger = &logger;
    def.spatial.minAttenuationDistance = 1.0f;
    def.spatial.maxAttenuationDistance = 60.0f;
    def.spatial.minPanningDistance = 1.0f;
    def.spatial.maxPanningDistance = 20.0f;
    return def;
}

au::SoundData tone(double seconds) {
    au::SoundData data;
    data.channels = 1;
    data.sampleRate = kRate;
    const auto frames = static_cast<std::size_t>(seconds * kRate);
    data.samples.resize(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        data.samples[i] =
            static_cast<float>(0.1 * std::sin(2.0 * std::numbers::pi * 440.0 * i / kRate));
    }
    return data;
}

// 256 spatial voices on circles around a listener that walks; every frame each voice gets a new
// position, the listener moves, and update() recomputes and sets every voice's two gains.
void BM_SpatialUpdate(benchmark::State& state) {
    const int voices = static_cast<int>(state.range(0));
    e2d::core::Logger logger(e2d::core::LogLevel::Warning);
    au::Mixer mixer(loopbackDef(logger, voices));
    const au::SoundId sound = mixer.add(tone(1.0), "tone");
    std::vector<au::VoiceId> ids;
    au::PlayDef play;
    play.loop = true;
    play.spatial = true;
    for (int i = 0; i < voices; ++i) {
        ids.push_back(mixer.play(sound, play));
    }
    if (mixer.stats().voicesInUse != voices) {
        state.SkipWithError("not every voice started");
        return;
    }
    double t = 0.0;
    const double dt = 1.0 / 60.0;
    for (auto _ : state) {
        t += dt;
        const glm::vec2 listener{static_cast<float>(10.0 * std::sin(0.3 * t)),
                                 static_cast<float>(2.0 * t)};
        mixer.setListener(listener, 0.0f);
        for (int i = 0; i < voices; ++i) {
            const double a = t * (0.5 + 0.01 * i) + i;
            const float r = 2.0f + 0.2f * static_cast<float>(i % 200);
            mixer.setPosition(ids[static_cast<std::size_t>(i)],
                              listener + glm::vec2{r * static_cast<float>(std::cos(a)),
                                                   r * static_cast<float>(std::sin(a))});
        }
        mixer.update(dt);
    }
    state.counters["us_per_frame"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetItemsProcessed(state.iterations() * voices);
}
BENCHMARK(BM_SpatialUpdate)->Arg(256)->Unit(benchmark::kMicrosecond);

// OpenAL Soft mixing 64 voices (mono, spatial, looping, different pitches so the resampler
// works) into 1 s of stereo floats through the loopback device.
void BM_LoopbackRender(benchmark::State& state) {
    const int voices = static_cast<int>(state.range(0));
    e2d::core::Logger logger(e2d::core::LogLevel::Warning);
    au::Mixer mixer(loopbackDef(logger, voices));
    const au::SoundId sound = mixer.add(tone(2.0), "tone");
    for (int i = 0; i < voices; ++i) {
        au::PlayDef play;
        play.loop = true;
        play.spatial = true;
        play.position = {static_cast<float>(i % 16) * 2.0f - 16.0f, static_cast<float>(i / 16)};
        play.pitch = 0.75f + 0.01f * static_cast<float>(i);
        mixer.play(sound, play);
    }
    mixer.update(0.0);
    std::vector<float> out(2 * kRate);
    for (auto _ : state) {
        mixer.render(out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["realtime_x"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.SetLabel(std::to_string(voices) + " voices, 1 s at 48 kHz per iteration");
}
BENCHMARK(BM_LoopbackRender)->Arg(64)->Unit(benchmark::kMillisecond);

// The streaming path: the decoder a playing stream uses, read in 0.1 s chunks to the end.
void decodeStream(benchmark::State& state, const std::filesystem::path& path) {
    std::int64_t frames = 0;
    for (auto _ : state) {
        std::string error;
        auto decoder = au::detail::Decoder::open(path, {}, error);
        if (!decoder) {
            state.SkipWithError(error.c_str());
            return;
        }
        const std::int64_t chunk = decoder->sampleRate() / 10;
        std::vector<float> buffer(static_cast<std::size_t>(chunk * decoder->channels()));
        frames = 0;
        for (std::int64_t got; (got = decoder->read(buffer.data(), chunk)) > 0;) {
            frames += got;
        }
        benchmark::DoNotOptimize(buffer.data());
    }
    state.SetItemsProcessed(state.iterations() * frames);
    state.counters["realtime_x"] = benchmark::Counter(static_cast<double>(state.iterations()) *
                                                          static_cast<double>(frames) / 44100.0,
                                                      benchmark::Counter::kIsRate);
}

void decodeWhole(benchmark::State& state, const std::filesystem::path& path) {
    std::int64_t frames = 0;
    for (auto _ : state) {
        const au::DecodeResult result = au::decodeSoundFile(path);
        if (!result.ok()) {
            state.SkipWithError(result.error.c_str());
            return;
        }
        frames = result.data.frames();
        benchmark::DoNotOptimize(result.data.samples.data());
    }
    state.SetItemsProcessed(state.iterations() * frames);
    state.counters["realtime_x"] = benchmark::Counter(static_cast<double>(state.iterations()) *
                                                          static_cast<double>(frames) / 44100.0,
                                                      benchmark::Counter::kIsRate);
}

void BM_DecodeOggStream(benchmark::State& s) {
    decodeStream(s, writeFile("music.ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS, 10.0));
}
void BM_DecodeOggWhole(benchmark::State& s) {
    decodeWhole(s, writeFile("music.ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS, 10.0));
}
void BM_DecodeFlacStream(benchmark::State& s) {
    decodeStream(s, writeFile("music.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 10.0));
}
void BM_DecodeFlacWhole(benchmark::State& s) {
    decodeWhole(s, writeFile("music.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 10.0));
}
BENCHMARK(BM_DecodeOggStream)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeOggWhole)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeFlacStream)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeFlacWhole)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    ::setenv("ALSOFT_DRIVERS", "null", 0);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::error_code ec;
    std::filesystem::remove_all(benchDir(), ec);
    return 0;
}
