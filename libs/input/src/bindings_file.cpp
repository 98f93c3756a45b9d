// SPDX-License-Identifier: MIT
// Bindings files: `name = binding, binding, ...`, one action per line.
#include "action_name.hpp"

#include <e2d/input/actions.hpp>

#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>

namespace e2d::input {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
        s.remove_prefix(1);
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
        s.remove_suffix(1);
    }
    return s;
}

} // namespace

void ActionMap::loadFromString(std::string_view text, std::string_view source) {
    // Parse everything first, so an error leaves the map unchanged.
    std::vector<std::pair<std::string, std::vector<Binding>>> parsed;
    text = core::withoutByteOrderMark(text);
    int lineNumber = 0;
    const auto fail = [&](const std::string& what) {
        throw core::ParseError(core::Diagnostic{
            core::Severity::Error, core::printable(source), lineNumber, 0, {}, what});
    };
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t end = text.find('\n');
        const std::string_view line = trim(text.substr(0, end));
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const std::size_t equals = line.find('=');
        if (equals == std::string_view::npos) {
            fail("expected '<action> = <binding>, ...'");
        }
        const std::string_view name = trim(line.substr(0, equals));
        if (!detail::isActionName(name)) {
            fail(std::string(detail::kActionNameRule) + ", got " + core::quote(name));
        }
        for (const auto& [previous, unused] : parsed) {
            if (previous == name) {
                fail("action '" + std::string(name) + "' is listed twice");
            }
        }
        std::vector<Binding> bindings;
        std::string_view rest = trim(line.substr(equals + 1));
        while (!rest.empty()) {
            const std::size_t comma = rest.find(',');
            const std::string_view item = trim(rest.substr(0, comma));
            rest =
                comma == std::string_view::npos ? std::string_view{} : trim(rest.substr(comma + 1));
            if (item.empty()) {
                fail("empty binding");
            }
            try {
                Binding b = parseBinding(item);
                if (std::find(bindings.begin(), bindings.end(), b) == bindings.end()) {
                    bindings.push_back(b);
                }
            } catch (const core::Error& e) {
                // Drop parseBinding's own prefix: the file position says where.
                std::string_view what = e.what();
                constexpr std::string_view kPrefix = "input::parseBinding(): ";
                if (what.starts_with(kPrefix)) {
                    what.remove_prefix(kPrefix.size());
                }
                fail(std::string(what));
            }
        }
        parsed.emplace_back(std::string(name), std::move(bindings));
    }
    for (auto& [name, bindings] : parsed) {
        actions_[findOrAdd(name).index()].bindings = std::move(bindings);
    }
}

void ActionMap::load(const std::filesystem::path& path) {
    loadFromString(core::readRequiredTextFile(path, "input::ActionMap::load()"), path.string());
}

std::string ActionMap::toString() const {
    std::string out = "# e2d input bindings: <action> = <binding>, ...\n";
    for (const Action& action : actions_) {
        out += action.name;
        out += " =";
        for (std::size_t i = 0; i < action.bindings.size(); ++i) {
            out += i == 0 ? " " : ", ";
            out += formatBinding(action.bindings[i]);
        }
        out += '\n';
    }
    return out;
}

void ActionMap::save(const std::filesystem::path& path) const {
    const std::string text = toString();
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file || !file.write(text.data(), static_cast<std::streamsize>(text.size())) ||
        !file.flush()) {
        throw core::Error("input::ActionMap::save(): cannot write '" + path.string() + "'");
    }
}

} // namespace e2d::input
