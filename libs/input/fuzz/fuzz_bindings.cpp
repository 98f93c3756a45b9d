// SPDX-License-Identifier: MIT
// Arbitrary bytes as a bindings file: loading either succeeds or throws core::Error and leaves
// the map as it was; a loaded map saves to text that loads back to the same map.
#include <e2d/core/error.hpp>
#include <e2d/input/actions.hpp>

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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    e2d::input::ActionMap actions;
    actions.bind(actions.add("keep"), e2d::input::Binding::key(e2d::input::Key::Space));
    const std::string before = actions.toString();
    try {
        actions.loadFromString(text, "fuzz");
    } catch (const e2d::core::Error& e) {
        check(std::string_view(e.what()).starts_with("fuzz:"));
        check(actions.toString() == before);
        return 0;
    }
    const std::string saved = actions.toString();
    e2d::input::ActionMap reloaded;
    reloaded.loadFromString(saved, "saved");
    check(reloaded.toString() == saved);
    return 0;
}
