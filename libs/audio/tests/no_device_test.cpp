// SPDX-License-Identifier: MIT
// No sound device: one clear line in the log, then silence. OpenAL Soft reads its settings once
// per process, so the check runs the mixer in a child process with its own environment.
#include "audio_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstring>
#include <sstream>

extern char** environ;

namespace e2d::audio {
namespace {

using ::testing::HasSubstr;
using namespace test;

// Run only by NoDevice.OneLineThenSilence, in a child process: a mixer on the default device,
// logging to stderr, and a sound played into the silence.
TEST(NoDeviceChild, DISABLED_MixerOnTheDefaultDevice) {
    core::Logger logger; // "[level] message" on stderr
    MixerDef def;
    def.output = Output::Device;
    def.logger = &logger;
    Mixer mixer(def);
    EXPECT_FALSE(mixer.hasDevice());
    const SoundId tone = mixer.add(SoundData{1, 48000, sine(440.0, 0.1, 48000)});
    EXPECT_FALSE(mixer.play(tone).isNull());
    mixer.update(0.05);
    mixer.update(0.1);
    EXPECT_EQ(mixer.stats().voicesInUse, 0);
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        out.push_back(line);
    }
    return out;
}

// ALSA given a configuration that defines no device: the same failure on every machine, with a
// sound card or without. Before, the game's stderr got ALSA's and OpenAL Soft's own lines
// ("ALSA lib pcm.c:2666:(snd_pcm_open_noupdate) Unknown PCM default", "AL lib: (EE) ...") and
// nine of them without a card; now one warning says what happened and how to choose silence.
TEST(NoDevice, OneLineThenSilence) {
    const auto alsaConfig = writeBytes("alsa.conf", {});
    const auto outPath = tempDir() / "child.out";
    const auto errPath = tempDir() / "child.err";
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
        if (std::strncmp(*e, "ALSOFT_", 7) != 0 && std::strncmp(*e, "ALSA_", 5) != 0) {
            env.emplace_back(*e);
        }
    }
    env.push_back("ALSOFT_DRIVERS=alsa");
    env.push_back("ALSA_CONFIG_PATH=" + alsaConfig.string());
    std::vector<char*> envp;
    for (std::string& e : env) {
        envp.push_back(e.data());
    }
    envp.push_back(nullptr);
    std::string self = "/proc/self/exe";
    std::string filter = "--gtest_filter=NoDeviceChild.DISABLED_MixerOnTheDefaultDevice";
    std::string disabled = "--gtest_also_run_disabled_tests";
    char* argv[] = {self.data(), filter.data(), disabled.data(), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, self.c_str(), &actions, nullptr, argv, envp.data()), 0);
    posix_spawn_file_actions_destroy(&actions);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    const auto out = readBytes(outPath);
    const auto err = readBytes(errPath);
    const std::string stdoutText(out.begin(), out.end());
    const std::string stderrText(err.begin(), err.end());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << stdoutText << stderrText;
    EXPECT_THAT(stdoutText, HasSubstr("[  PASSED  ] 1 test"));
    const auto said = lines(stderrText);
    ASSERT_EQ(said.size(), 1u) << stderrText;
    EXPECT_THAT(said[0], HasSubstr("[warning] audio::Mixer: no default audio device"));
    EXPECT_THAT(
        said[0],
        HasSubstr(
            "; running silent (ALSOFT_DRIVERS=null chooses silence without looking for a device)"));
}

} // namespace
} // namespace e2d::audio
