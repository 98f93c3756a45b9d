// SPDX-License-Identifier: MIT
// e2d::audio alone from an install: a tone played on the right, mixed by the loopback device.
#include <e2d/audio/mixer.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main() {
    ::setenv("ALSOFT_DRIVERS", "null", 0);
    using namespace e2d::audio;
    MixerDef def;
    def.output = Output::Loopback;
    Mixer mixer(def);
    SoundData tone;
    tone.channels = 1;
    tone.sampleRate = 48000;
    for (int i = 0; i < 48000; ++i) {
        tone.samples.push_back(
            0.5f * static_cast<float>(std::sin(2.0 * 3.14159265358979 * 1000.0 * i / 48000.0)));
    }
    PlayDef play;
    play.spatial = true;
    play.attenuationFactor = 0.0f;
    play.position = {100.0f, 0.0f};
    mixer.play(mixer.add(tone), play);
    mixer.update(0.0);
    std::vector<float> out(2 * 4800);
    mixer.render(out);
    double left = 0.0;
    double right = 0.0;
    for (std::size_t i = 0; i < out.size(); i += 2) {
        left += out[i] * out[i];
        right += out[i + 1] * out[i + 1];
    }
    left = std::sqrt(left / 4800);
    right = std::sqrt(right / 4800);
    if (left > 1e-4 || std::abs(right - 0.5 / std::sqrt(2.0)) > 0.01) {
        std::fprintf(stderr, "consumer: e2d::audio unexpected mix (left %.4f, right %.4f)\n", left,
                     right);
        return 1;
    }
    std::printf("consumer: e2d::audio a tone on the right: left RMS %.4f, right RMS %.4f\n", left,
                right);
    return 0;
}
