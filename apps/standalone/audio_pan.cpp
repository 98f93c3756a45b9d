// SPDX-License-Identifier: MIT
// e2d::audio alone: a Mixer and nothing else. A tone made in memory plays for one second while
// it moves from the listener's left to its right, so it pans across. Plays on the default
// sound device; with --loopback it is mixed into memory instead, and the program checks that
// the sound went from the left channel to the right (exit 1 if not). Links e2d::audio only.
// No sound card: run it with ALSOFT_DRIVERS=null (OpenAL Soft's silent device).
#include <e2d/audio/mixer.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

using namespace e2d::audio;

int main(int argc, char** argv) {
    const bool loopback = argc > 1 && std::string(argv[1]) == "--loopback";

    // Initialisation: the mixer opens the device (or the loopback device) and its voices.
    Mixer mixer(MixerDef{.output = loopback ? Output::Loopback : Output::Device});
    SoundData tone{.channels = 1, .sampleRate = 48000, .samples = {}};
    for (int i = 0; i < 48000; ++i) { // one second of a 440 Hz sine at half scale
        tone.samples.push_back(
            0.5f * std::sin(2.0f * 3.14159265f * 440.0f * static_cast<float>(i) / 48000.0f));
    }
    const SoundId sound = mixer.add(std::move(tone), "tone");
    // Spatial: heard from its position relative to the listener (at (0, 0), world units).
    const VoiceId voice =
        mixer.play(sound, {.loop = true, .spatial = true, .position = {-8.0f, 0.0f}});

    // The loop: 60 frames of 1/60 s; each moves the voice and lets the mixer catch up.
    float left[2] = {0.0f, 0.0f}; // energy per channel in the first and last quarter second
    float right[2] = {0.0f, 0.0f};
    std::vector<float> mix(2 * 48000 / 60); // one frame of stereo floats: L, R, L, R, ...
    for (int frame = 0; frame < 60; ++frame) {
        mixer.setPosition(voice, {-8.0f + 16.0f * static_cast<float>(frame) / 59.0f, 0.0f});
        mixer.update(1.0 / 60.0); // fades, streams and positions
        if (!loopback) {
            std::this_thread::sleep_for(std::chrono::microseconds(16667)); // the device plays it
            continue;
        }
        mixer.render(mix); // the loopback device mixes the next 1/60 s here
        const int quarter = frame < 15 ? 0 : frame >= 45 ? 1 : -1;
        for (std::size_t i = 0; quarter >= 0 && i < mix.size(); i += 2) {
            left[quarter] += mix[i] * mix[i];
            right[quarter] += mix[i + 1] * mix[i + 1];
        }
    }

    // Shutdown: stop with a short fade; the mixer closes its device when it goes.
    mixer.stop(voice, 0.05);
    if (!loopback) {
        return 0;
    }
    std::printf("first quarter: left %.1f, right %.1f; last quarter: left %.1f, right %.1f\n",
                left[0], right[0], left[1], right[1]);
    return left[0] > 2.0f * right[0] && right[1] > 2.0f * left[1] ? 0 : 1;
}
