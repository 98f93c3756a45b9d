// SPDX-License-Identifier: MIT
// Arbitrary bytes as an input script: parsing either succeeds or throws core::Error naming the
// source and a line, with nothing unprintable in the message; parsed events are sorted, on
// bounded frames; played into a detached Input (targets resolved against a small action map),
// every event is fed without a crash.
#include <e2d/core/error.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/input_script.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

bool printableMessage(std::string_view message) {
    return std::none_of(message.begin(), message.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte < 0x20 || byte == 0x7F;
    });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace e2d;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    input::InputScript script;
    try {
        script = input::parseInputScript(text, "fuzz");
    } catch (const core::Error& e) {
        check(std::string_view(e.what()).starts_with("fuzz:"));
        check(printableMessage(e.what()));
        return 0;
    }
    std::int64_t last = 0;
    for (const input::ScriptEvent& event : script.events) {
        check(event.frame >= last && event.frame <= input::kMaxScriptFrame + 1);
        check(event.line >= 1);
        last = event.frame;
    }

    input::ActionMap actions;
    actions.bind(actions.add("jump"), input::Binding::key(input::Key::Space));
    actions.bind(actions.add("steer"), input::Binding::gamepadAxis(input::GamepadAxis::LeftX));
    try {
        input::ScriptedInput device(script, actions);
        input::Input in;
        // Frame 0, then everything else at once (frames may be up to 10^9 apart).
        device.feed(in, 0);
        in.beginFrame();
        actions.update(in);
        device.feed(in, input::kMaxScriptFrame + 1);
        in.beginFrame();
        actions.update(in);
        check(device.finished());
    } catch (const core::Error& e) {
        check(std::string_view(e.what()).starts_with("fuzz:"));
    }
    return 0;
}
