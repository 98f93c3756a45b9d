// SPDX-License-Identifier: MIT
#include "sound_decoder.hpp"

#include "ogg_pages.hpp"
#include "riff_chunks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace e2d::audio::detail {

namespace {

bool startsWith(std::span<const std::byte> bytes, std::size_t offset, std::string_view tag) {
    return bytes.size() >= offset + tag.size() &&
           std::memcmp(bytes.data() + offset, tag.data(), tag.size()) == 0;
}

// An Ogg container (libsndfile reads it as Ogg by the same capture pattern).
bool isOgg(std::span<const std::byte> head) { return startsWith(head, 0, "OggS"); }

// The formats e2d reads are WAV, Ogg and FLAC. libsndfile guesses among about twenty more from
// the bytes (MPEG through libmpg123, PAF, IRCAM, ...), and some of those parsers never return on
// damaged input (a fuzzed MPEG stream kept sf_open_virtual() busy for 20 minutes): anything
// else is refused before libsndfile sees it. Empty when `head` (the first bytes) starts one of
// the three, else the reason.
bool isWav(std::span<const std::byte> head) {
    return (startsWith(head, 0, "RIFF") || startsWith(head, 0, "RIFX") ||
            startsWith(head, 0, "RF64")) &&
           startsWith(head, 8, "WAVE");
}

std::string unsupportedFormat(std::span<const std::byte> head) {
    if (isWav(head) || isOgg(head) || startsWith(head, 0, "fLaC")) {
        return {};
    }
    return "not a WAV, Ogg or FLAC file (the formats e2d::audio reads)";
}

// libsndfile's virtual I/O over a block of memory (Decoder::Memory).
using MemoryCursor = Decoder::Memory;

sf_count_t vioLength(void* user) {
    return static_cast<sf_count_t>(static_cast<MemoryCursor*>(user)->bytes.size());
}

sf_count_t vioSeek(sf_count_t offset, int whence, void* user) {
    auto* cursor = static_cast<MemoryCursor*>(user);
    const auto size = static_cast<sf_count_t>(cursor->bytes.size());
    sf_count_t base = 0;
    switch (whence) {
    case SEEK_CUR:
        base = cursor->position;
        break;
    case SEEK_END:
        base = size;
        break;
    default:
        break;
    }
    // Guard the addition: a corrupt header can ask for any offset.
    if ((offset > 0 && base > std::numeric_limits<sf_count_t>::max() - offset) ||
        base + offset < 0) {
        return -1;
    }
    cursor->position = base + offset;
    return cursor->position;
}

sf_count_t vioRead(void* ptr, sf_count_t count, void* user) {
    auto* cursor = static_cast<MemoryCursor*>(user);
    const auto size = static_cast<sf_count_t>(cursor->bytes.size());
    if (count <= 0 || cursor->position >= size) {
        return 0;
    }
    const sf_count_t n = std::min(count, size - cursor->position);
    std::memcpy(ptr, cursor->bytes.data() + cursor->position, static_cast<std::size_t>(n));
    cursor->position += n;
    return n;
}

sf_count_t vioWrite(const void*, sf_count_t, void*) { return 0; }

sf_count_t vioTell(void* user) { return static_cast<MemoryCursor*>(user)->position; }

// The bytes of a file; empty if it cannot be read.
std::vector<std::byte> fileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = file ? static_cast<std::streamoff>(file.tellg()) : 0;
    std::vector<std::byte> bytes(static_cast<std::size_t>(std::max<std::streamoff>(size, 0)));
    file.seekg(0);
    if (!file.read(reinterpret_cast<char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()))) {
        bytes.clear();
    }
    return bytes;
}

// checkWavChunks reading a block of memory.
ReadAt memoryReader(std::span<const std::byte> bytes) {
    return [bytes](std::uint64_t offset, std::span<std::byte> out) -> std::size_t {
        if (offset >= bytes.size()) {
            return 0;
        }
        const auto count =
            static_cast<std::size_t>(std::min<std::uint64_t>(out.size(), bytes.size() - offset));
        std::memcpy(out.data(), bytes.data() + offset, count);
        return count;
    };
}

// checkWavChunks reading an open file.
ReadAt fileReader(std::ifstream& file) {
    return [&file](std::uint64_t offset, std::span<std::byte> out) -> std::size_t {
        file.clear();
        file.seekg(static_cast<std::streamoff>(offset));
        file.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(out.size()));
        return static_cast<std::size_t>(std::max<std::streamsize>(file.gcount(), 0));
    };
}

std::string seconds(std::int64_t frames, int rate) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f s", static_cast<double>(frames) / rate);
    return text;
}

} // namespace

std::unique_ptr<Decoder> Decoder::open(const std::filesystem::path& path,
                                       const DecodeLimits& limits, std::string& error,
                                       bool checked) {
    std::unique_ptr<Decoder> decoder(new Decoder());
    decoder->name_ = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        error = "'" + decoder->name_ + "': no such file";
        return nullptr;
    }
    if (std::filesystem::is_directory(path, ec)) {
        error = "'" + decoder->name_ + "': is a directory";
        return nullptr;
    }
    {
        std::array<std::byte, 12> head{};
        std::ifstream file(path, std::ios::binary);
        file.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
        const auto got = static_cast<std::size_t>(std::max<std::streamsize>(file.gcount(), 0));
        const std::span<const std::byte> read = std::span(head).first(got);
        std::string problem = unsupportedFormat(read);
        if (problem.empty() && !checked) {
            if (isOgg(read)) {
                problem = checkOggPages(fileBytes(path));
            } else if (isWav(read)) {
                problem = checkWavChunks(std::filesystem::file_size(path, ec), fileReader(file));
            }
        }
        if (!problem.empty()) {
            error = "'" + decoder->name_ + "': " + problem;
            return nullptr;
        }
    }
    decoder->file_ = sf_open(decoder->name_.c_str(), SFM_READ, &decoder->info_);
    if (!decoder->finishOpen(limits, error)) {
        return nullptr;
    }
    return decoder;
}

std::unique_ptr<Decoder> Decoder::open(std::span<const std::byte> bytes, std::string_view name,
                                       const DecodeLimits& limits, std::string& error) {
    std::unique_ptr<Decoder> decoder(new Decoder());
    decoder->name_ = std::string(name);
    std::string problem = unsupportedFormat(bytes);
    if (problem.empty() && isOgg(bytes)) {
        problem = checkOggPages(bytes);
    } else if (problem.empty() && isWav(bytes)) {
        problem = checkWavChunks(bytes.size(), memoryReader(bytes));
    }
    if (!problem.empty()) {
        error = "'" + decoder->name_ + "': " + problem;
        return nullptr;
    }
    decoder->memory_ = Memory{bytes, 0};
    SF_VIRTUAL_IO io{vioLength, vioSeek, vioRead, vioWrite, vioTell};
    decoder->file_ = sf_open_virtual(&io, SFM_READ, &decoder->info_, &decoder->memory_);
    if (!decoder->finishOpen(limits, error)) {
        return nullptr;
    }
    return decoder;
}

bool Decoder::finishOpen(const DecodeLimits& limits, std::string& error) {
    const std::string prefix = "'" + name_ + "': ";
    if (file_ == nullptr) {
        error = prefix + sf_strerror(nullptr);
        return false;
    }
    if (info_.channels < 1 || info_.channels > limits.maxChannels) {
        error = prefix + std::to_string(info_.channels) + " channels, at most " +
                std::to_string(limits.maxChannels) + " supported";
        return false;
    }
    if (info_.samplerate < limits.minSampleRate || info_.samplerate > limits.maxSampleRate) {
        error = prefix + "sample rate " + std::to_string(info_.samplerate) + " Hz outside " +
                std::to_string(limits.minSampleRate) + ".." + std::to_string(limits.maxSampleRate) +
                " Hz";
        return false;
    }
    // libsndfile reads a data chunk that claims more bytes than the file holds up to the end
    // of the file, and only notes it in its log ("data : 8820 (should be 1000)"): a truncated
    // or mis-sized file, which is an error here.
    std::string log(4096, '\0');
    sf_command(file_, SFC_GET_LOG_INFO, log.data(), static_cast<int>(log.size()));
    log.resize(log.find('\0'));
    for (std::size_t begin = 0; begin < log.size();) {
        std::size_t end = log.find('\n', begin);
        end = end == std::string::npos ? log.size() : end;
        const std::string_view line(log.data() + begin, end - begin);
        if (line.starts_with("data") && line.find("(should be") != std::string_view::npos) {
            error =
                prefix + "truncated or wrong chunk size (libsndfile: " + std::string(line) + ")";
            return false;
        }
        begin = end + 1;
    }
    // libsndfile says SF_COUNT_MAX when the length is unknown.
    headerFrames_ = info_.frames == SF_COUNT_MAX ? -1 : static_cast<std::int64_t>(info_.frames);
    if (headerFrames_ == 0 || headerFrames_ < -1) {
        error = prefix + "no audio frames";
        return false;
    }
    maxMagnitude_ = limits.maxSampleMagnitude;
    return true;
}

Decoder::~Decoder() {
    if (file_ != nullptr) {
        sf_close(file_);
    }
}

void Decoder::setError(std::string_view reason) {
    error_ = "'" + name_ + "': ";
    error_ += reason;
}

std::string Decoder::where(std::int64_t frame) const {
    return seconds(frame, info_.samplerate) + " (frame " + std::to_string(frame) + ")";
}

std::int64_t Decoder::read(float* out, std::int64_t frames) {
    // libsndfile may return fewer frames than asked before the end: only 0 means the end.
    std::int64_t got = 0;
    while (got < frames) {
        const sf_count_t n = sf_readf_float(file_, out + got * info_.channels,
                                            static_cast<sf_count_t>(frames - got));
        if (sf_error(file_) != SF_ERR_NO_ERROR) {
            setError("damaged or truncated: decoding stopped at " + where(position_ + got) +
                     " (libsndfile: " + sf_strerror(file_) + ")");
            return -1;
        }
        if (n <= 0) {
            break;
        }
        got += n;
    }
    const std::int64_t values = got * info_.channels;
    for (std::int64_t i = 0; i < values; ++i) {
        const float v = out[i];
        if (!(std::abs(v) <= maxMagnitude_)) {
            std::ostringstream problem;
            problem << "damaged: sample " << v << " at " << where(position_ + i / info_.channels)
                    << " is ";
            if (std::isfinite(v)) {
                problem << "beyond +-" << maxMagnitude_ << " (DecodeLimits::maxSampleMagnitude)";
            } else {
                problem << "not finite";
            }
            setError(problem.str());
            return -1;
        }
    }
    position_ += got;
    if (got < frames && headerFrames_ > 0 && position_ < headerFrames_) {
        setError("damaged or truncated: the header announces " + std::to_string(headerFrames_) +
                 " frames (" + seconds(headerFrames_, info_.samplerate) +
                 "), the data ends after " + std::to_string(position_) + " (" +
                 seconds(position_, info_.samplerate) + ")");
        return -1;
    }
    return got;
}

bool Decoder::seek(std::int64_t frame) {
    if (sf_seek(file_, static_cast<sf_count_t>(frame), SEEK_SET) < 0) {
        setError(std::string("cannot seek: ") + sf_strerror(file_));
        return false;
    }
    position_ = frame;
    return true;
}

DecodeResult Decoder::readAll(std::int64_t maxFrames) {
    DecodeResult result;
    if (headerFrames_ > maxFrames) {
        result.error = "'" + name_ + "': " + std::to_string(headerFrames_) +
                       " frames, more than the limit of " + std::to_string(maxFrames);
        return result;
    }
    const int channels = info_.channels;
    constexpr std::int64_t kChunk = 16384;
    // The header is untrusted: reserve at most a few MiB up front and grow as data arrives.
    std::vector<float> samples;
    if (headerFrames_ > 0) {
        samples.reserve(
            static_cast<std::size_t>(std::min<std::int64_t>(headerFrames_, 1 << 20) * channels));
    }
    std::int64_t total = 0;
    for (;;) {
        const std::int64_t want = std::min(kChunk, maxFrames + 1 - total);
        samples.resize(static_cast<std::size_t>((total + want) * channels));
        const std::int64_t got = read(samples.data() + total * channels, want);
        if (got < 0) {
            result.error = error_;
            return result;
        }
        total += got;
        if (total > maxFrames) {
            result.error =
                "'" + name_ + "': more than the limit of " + std::to_string(maxFrames) + " frames";
            return result;
        }
        if (got < want) {
            break;
        }
    }
    samples.resize(static_cast<std::size_t>(total * channels));
    if (total == 0) {
        result.error = "'" + name_ + "': no audio frames";
        return result;
    }
    result.data.channels = channels;
    result.data.sampleRate = info_.samplerate;
    result.data.samples = std::move(samples);
    return result;
}

} // namespace e2d::audio::detail

namespace e2d::audio {

DecodeResult decodeSoundFile(const std::filesystem::path& path, const DecodeLimits& limits) {
    DecodeResult result;
    auto decoder = detail::Decoder::open(path, limits, result.error);
    if (!decoder) {
        return result;
    }
    return decoder->readAll(limits.maxFrames);
}

DecodeResult decodeSoundMemory(std::span<const std::byte> bytes, std::string_view name,
                               const DecodeLimits& limits) {
    DecodeResult result;
    auto decoder = detail::Decoder::open(bytes, name, limits, result.error);
    if (!decoder) {
        return result;
    }
    return decoder->readAll(limits.maxFrames);
}

} // namespace e2d::audio
