// SPDX-License-Identifier: MIT
#include <e2d/engine/command_line.hpp>

#include <e2d/core/error.hpp>

#include <charconv>

namespace e2d::engine {

namespace {

template <class Int>
Int wholeNumber(std::string_view option, std::string_view text, Int min) {
    Int value{};
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || value < min) {
        throw core::Error(std::string(option) + ": expected a whole number >= " +
                          std::to_string(min) + ", got '" + std::string(text) + "'");
    }
    return value;
}

} // namespace

CommandLine parseCommandLine(std::span<const std::string_view> args) {
    CommandLine out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string_view arg = args[i];
        std::string_view inlineValue;
        bool hasInline = false;
        if (arg.starts_with("--")) {
            if (const std::size_t eq = arg.find('='); eq != std::string_view::npos) {
                inlineValue = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                hasInline = true;
            }
        }
        const auto value = [&]() -> std::string_view {
            if (hasInline) {
                if (inlineValue.empty()) {
                    throw core::Error(std::string(arg) + ": missing value");
                }
                return inlineValue;
            }
            if (i + 1 >= args.size() || args[i + 1].empty()) {
                throw core::Error(std::string(arg) + ": missing value");
            }
            return args[++i];
        };
        const auto flag = [&] {
            if (hasInline) {
                throw core::Error(std::string(arg) + ": takes no value");
            }
        };
        if (arg == "--frames") {
            out.frames = wholeNumber<std::int64_t>(arg, value(), 1);
        } else if (arg == "--screenshot") {
            out.screenshot = value();
        } else if (arg == "--config") {
            out.config = value();
        } else if (arg == "--seed") {
            out.seed = wholeNumber<std::uint64_t>(arg, value(), 0);
        } else if (arg == "--input-script") {
            out.inputScript = value();
        } else if (arg == "--debug-draw") {
            flag();
            out.debugDraw = true;
        } else if (arg == "--profile") {
            flag();
            out.profile = true;
        } else if (arg == "--show") {
            flag();
            out.show = true;
        } else if (arg == "--help" || arg == "-h") {
            flag();
            out.help = true;
        } else {
            throw core::Error("unknown argument '" + std::string(args[i]) + "'");
        }
    }
    return out;
}

std::string usage(std::string_view program) {
    return "usage: " + std::string(program) +
           " [options]\n"
           "  --config FILE        configuration file (default: config.txt beside the program)\n"
           "  --frames N           run N frames of exactly 1/60 s, then exit (hidden window)\n"
           "  --screenshot FILE    save the last frame as a PNG\n"
           "  --seed N             seed of the game's random numbers\n"
           "  --input-script FILE  timed input, one per line: '<frame> <press|release|tap> "
           "<action, key:x,\n"
           "                       mouse:left or button:a>', '<frame> move mouse <x> <y>', "
           "'<frame> move axis:leftx <v>'\n"
           "  --debug-draw         start with the physics debug draw on\n"
           "  --profile            start with the frame profile overlay on\n"
           "  --show               keep the window visible with --frames\n"
           "  --help               this text\n";
}

} // namespace e2d::engine
