// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/audio/ids.hpp>
#include <e2d/audio/sound_data.hpp>
#include <e2d/audio/spatial.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace e2d::core {
class Logger;
}

/// Sound playback through OpenAL Soft: an owned device and context, a cache of sounds, a fixed
/// pool of voices with priorities, streaming, fades, buses and a 2D spatial model (spatial.hpp).
namespace e2d::audio {

/// Where a Mixer sends its sound.
enum class Output {
    /// The device named by MixerDef::deviceName (empty: the system's default device).
    Device,
    /// OpenAL Soft's loopback device: nothing is played; `Mixer::render()` mixes the next
    /// frames into memory (stereo floats at MixerDef::loopbackSampleRate). For tests, offline
    /// rendering and measurements.
    Loopback,
    /// No output at all: the mixer runs silent from the start (as with no device).
    None,
};

/// Gain groups; a voice belongs to one. Each bus has its own gain (default 1).
enum class Bus : std::uint8_t { Music, Effects };
inline constexpr int kBusCount = 2;

/// How a sound is loaded.
enum class LoadMode {
    /// Decoded once into memory and shared by every voice playing it.
    Whole,
    /// Decoded in chunks while it plays (music, long ambiences): each voice playing it reads
    /// the file itself, a few chunks ahead.
    Stream,
};

/// What a voice is doing. A null, stale or finished voice is Stopped.
enum class VoiceState { Stopped, Playing, Paused };

/// Settings of a Mixer, validated by its constructor.
struct MixerDef {
    /// Receives the mixer's messages (no device, device lost, loading errors). Null: the mixer
    /// uses a logger of its own that writes to stderr. Must outlive the mixer. Default null.
    core::Logger* logger = nullptr;
    /// Default Device.
    Output output = Output::Device;
    /// OpenAL device name for Output::Device; empty means the default device. Default empty.
    std::string deviceName{};
    /// Hz, for Output::Loopback; 8000..192000. Default 48000.
    int loopbackSampleRate = 48000;
    /// For Output::Loopback: a loopback device the caller opened with OpenAL Soft's
    /// `alcLoopbackOpenDeviceSOFT` (an `ALCdevice*`, typed void* so that this header needs no
    /// OpenAL header). The mixer creates its context on it (stereo floats at
    /// loopbackSampleRate) and destroys that context, but never closes the device: the caller
    /// does, after the mixer is gone. The caller may render with `alcRenderSamplesSOFT` itself
    /// or through render(). Null: the mixer opens and closes a loopback device of its own.
    /// Default null.
    void* loopbackDevice = nullptr;
    /// Voices that can sound at once (each uses two OpenAL sources); 1..1024. Default 32.
    int voiceCount = 32;
    /// Multiplies every voice; >= 0. Default 1.
    float masterGain = 1.0f;
    /// Distances of the spatial model. Default: see SpatialDef. Need 0 <= min < max for both
    /// pairs.
    SpatialDef spatial{};
    /// Limits on the files the mixer loads. Default: see DecodeLimits.
    DecodeLimits limits{};
    /// Seconds of sound per stream buffer; 0.01..1. Default 0.1.
    double streamChunkSeconds = 0.1;
    /// Buffers queued per streaming voice; 3..16. All but one must hold at least 0.25 s, so a
    /// stream survives a frame that long: (count - 1) * chunk >= 0.25. Default 4.
    int streamChunkCount = 4;
};

/// How a voice starts, validated by Mixer::play().
struct PlayDef {
    /// Gain of this voice, >= 0 (1 = as recorded). Default 1.
    float gain = 1.0f;
    /// Playback speed and pitch factor, 0.01..16. Default 1.
    float pitch = 1.0f;
    /// Start again at the end, seamlessly (also for streams). Default false.
    bool loop = false;
    /// Positioned in the world and heard relative to the listener (spatial.hpp);
    /// otherwise it ignores positions. Default false.
    bool spatial = false;
    /// World units, for spatial voices. Default (0, 0).
    glm::vec2 position{0.0f, 0.0f};
    /// Divides the attenuation range (2 = silent at half the distance); 0 = no attenuation;
    /// >= 0. Default 1.
    float attenuationFactor = 1.0f;
    /// When every voice is busy, a sound takes the quietest voice of the lowest priority if
    /// that priority is lower than its own. Default 0.
    int priority = 0;
    /// Default Effects.
    Bus bus = Bus::Effects;
    /// Seconds to fade in from silence; >= 0 (0 = none). Default 0.
    double fadeIn = 0.0;
};

/// A loaded sound's description.
struct SoundInfo {
    std::string path; ///< as given to load()
    LoadMode mode = LoadMode::Whole;
    int channels = 0;        ///< 1 or 2; 0 when loading failed
    int sampleRate = 0;      ///< Hz; 0 when loading failed
    std::int64_t frames = 0; ///< samples per channel
    /// Empty when the sound loaded; otherwise why not (the file, then the reason). A sound that
    /// failed to load plays nothing.
    std::string error;

    [[nodiscard]] bool ok() const noexcept { return error.empty(); }
    [[nodiscard]] double duration() const noexcept {
        return sampleRate == 0 ? 0.0 : static_cast<double>(frames) / sampleRate;
    }
};

/// Counters for tests, tools and benchmarks.
struct MixerStats {
    int voicesInUse = 0;     ///< playing or paused voices
    int voicesStolen = 0;    ///< since the mixer was created
    int playsRefused = 0;    ///< play() calls that found no voice, since creation
    int streamUnderruns = 0; ///< times a stream ran dry and was restarted
};

/// Owns an OpenAL device and context (or a loopback device, or nothing) and everything played
/// through them. Not copyable, not thread-safe: use it from one thread.
///
/// Without a device (none found, Output::None, or lost while running) the mixer runs silent:
/// it says so once through the logger, every call still works, voices still start, fade and
/// end on time (their positions advance with update()), and `reopen()` tries the device again.
/// With no sound card, that is one warning with OpenAL Soft's reason; what OpenAL Soft and ALSA
/// print to stderr while the device fails to open goes to the logger's debug level instead.
/// `ALSOFT_DRIVERS=null` in the environment gives OpenAL Soft's silent device: no warning.
///
/// Call `update(dt)` once per frame: it advances fades, applies the spatial model, keeps
/// streams fed and retires voices that ended.
class Mixer {
public:
    /// Throws core::Error naming the invalid field of `def`
    /// (`"audio::Mixer::Mixer(): voiceCount must be in 1..1024, got 0"`). A missing device is
    /// not an error (see above).
    explicit Mixer(const MixerDef& def = {});
    ~Mixer();
    Mixer(const Mixer&) = delete;
    Mixer& operator=(const Mixer&) = delete;

    // Device ---------------------------------------------------------------------------------

    /// True when sound goes to a device (or the loopback device); false when running silent.
    [[nodiscard]] bool hasDevice() const noexcept;
    /// Output frequency in Hz (the device's, or 48000 when silent).
    [[nodiscard]] int sampleRate() const noexcept;
    /// Drops the current device (if any) and opens the system's default device (a loopback
    /// mixer: a new loopback device), moving every sound and voice onto it: voices go on from
    /// where they are. Returns hasDevice(); on failure the mixer stays silent and says so once.
    bool reopen();
    /// Mixes the next `interleavedStereo.size() / 2` frames into `interleavedStereo` (L, R, ...).
    /// Only for Output::Loopback with its device; otherwise throws core::Error. The size must
    /// be even.
    void render(std::span<float> interleavedStereo);

    // Sounds ---------------------------------------------------------------------------------

    /// The sound at `path`, loaded the first time it is asked for (per mode) and shared after.
    /// A file that cannot be loaded gives a sound all the same: its SoundInfo carries the
    /// error, which is logged once as an error, and it plays nothing. Whole sounds are
    /// decoded at once; streamed ones are opened and checked here, decoded while they play.
    /// Damaged and truncated files are refused by the rule of decodeSoundFile() in both modes;
    /// a stream that meets damage while playing stops there, and the error is logged once per
    /// sound.
    SoundId load(const std::filesystem::path& path, LoadMode mode = LoadMode::Whole);
    /// Adds decoded samples as a sound (not cached by path; `name` is for messages). Throws
    /// core::Error for 0 or more than 2 channels, a sample rate outside the limits, no frames,
    /// or a sample that is not finite or beyond `limits.maxSampleMagnitude`.
    SoundId add(SoundData data, std::string name = "<memory>");
    /// The sound's description; throws core::Error for a null or unknown id.
    [[nodiscard]] const SoundInfo& soundInfo(SoundId sound) const;
    /// Number of sounds loaded (failed ones included).
    [[nodiscard]] int soundCount() const noexcept;

    // Voices ---------------------------------------------------------------------------------

    /// Starts `sound` on a free voice. When none is free, it takes the quietest voice of the
    /// lowest priority if that priority is below `def.priority` (that voice stops at once and
    /// its id goes stale); otherwise nothing plays and the result is null (counted in
    /// stats().playsRefused). A sound that failed to load also gives null. Throws core::Error
    /// for an unknown sound id or an invalid field of `def`.
    VoiceId play(SoundId sound, const PlayDef& def = {});
    /// Stops the voice, at once or after fading out over `fadeOut` seconds. Returns false
    /// (doing nothing) for a null, stale or finished id. Throws core::Error for fadeOut < 0.
    bool stop(VoiceId voice, double fadeOut = 0.0);
    /// Pauses, at once or after fading out over `fadeOut` seconds; the voice keeps its place.
    bool pause(VoiceId voice, double fadeOut = 0.0);
    /// Resumes a paused voice where it stopped (or cancels a fade-out to pause), fading in over
    /// `fadeIn` seconds.
    bool resume(VoiceId voice, double fadeIn = 0.0);
    /// Stops every voice at once.
    void stopAll();

    [[nodiscard]] VoiceState state(VoiceId voice) const noexcept;
    [[nodiscard]] bool isValid(VoiceId voice) const noexcept {
        return state(voice) != VoiceState::Stopped;
    }
    /// The voice's sound (null for a stale id).
    [[nodiscard]] SoundId sound(VoiceId voice) const noexcept;

    /// Setters return false for a stale id and throw core::Error for invalid values (same
    /// ranges as PlayDef). Gain, position, attenuation and spatial changes (like the listener,
    /// bus and master gains) are heard from the next update(); pitch and loop at once.
    bool setGain(VoiceId voice, float gain);
    bool setPitch(VoiceId voice, float pitch);
    bool setLoop(VoiceId voice, bool loop);
    bool setPosition(VoiceId voice, glm::vec2 position);
    bool setAttenuationFactor(VoiceId voice, float factor);
    bool setSpatial(VoiceId voice, bool spatial);

    /// The gain the voice is heard at now, before panning: its gain * fade * bus * master *
    /// attenuation. 0 for a stale id.
    [[nodiscard]] float effectiveGain(VoiceId voice) const noexcept;
    /// Where the voice is in its sound, in seconds (0 for a stale id).
    [[nodiscard]] double playbackPosition(VoiceId voice) const;

    // Mix ------------------------------------------------------------------------------------

    [[nodiscard]] float masterGain() const noexcept;
    /// >= 0; throws core::Error otherwise.
    void setMasterGain(float gain);
    [[nodiscard]] float busGain(Bus bus) const noexcept;
    /// >= 0; throws core::Error otherwise.
    void setBusGain(Bus bus, float gain);

    /// The listener every spatial voice is heard from: world position, and orientation in
    /// radians counter-clockwise (its right ear points along its local +x).
    void setListener(glm::vec2 position, float orientation = 0.0f) noexcept;
    [[nodiscard]] glm::vec2 listenerPosition() const noexcept;
    [[nodiscard]] const SpatialDef& spatial() const noexcept;
    /// Throws core::Error unless 0 <= min < max for both pairs.
    void setSpatial(const SpatialDef& def);

    /// Advances fades and silent voices by `dt` seconds (>= 0), applies the spatial model to
    /// every voice, feeds streams, retires voices that ended, and notices a lost device.
    void update(double dt);

    [[nodiscard]] int voiceCount() const noexcept;
    [[nodiscard]] MixerStats stats() const noexcept;
    /// The logger the mixer reports to (the def's, or its own).
    [[nodiscard]] core::Logger& logger() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace e2d::audio
