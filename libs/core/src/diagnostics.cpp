// SPDX-License-Identifier: MIT
#include <e2d/core/diagnostics.hpp>

#include <algorithm>
#include <iterator>
#include <utility>

namespace e2d::core {

std::string Diagnostic::toString() const {
    std::string out = file;
    if (line > 0 && file.empty()) {
        out.append("line ").append(std::to_string(line));
        if (column > 0) {
            out.append(", column ").append(std::to_string(column));
        }
    } else if (line > 0) {
        out.append(":").append(std::to_string(line));
        if (column > 0) {
            out.append(":").append(std::to_string(column));
        }
    }
    if (!out.empty()) {
        out.append(": ");
    }
    if (!field.empty()) {
        out.append(field).append(": ");
    }
    return out.append(message);
}

void Diagnostics::add(Diagnostic diagnostic) {
    if (diagnostic.severity == Severity::Error) {
        ++errors_;
    }
    items_.push_back(std::move(diagnostic));
}

void Diagnostics::error(std::string_view file, int line, std::string message,
                        std::string_view field) {
    add(Diagnostic{Severity::Error, std::string(file), line, 0, std::string(field),
                   std::move(message)});
}

void Diagnostics::warning(std::string_view file, int line, std::string message,
                          std::string_view field) {
    add(Diagnostic{Severity::Warning, std::string(file), line, 0, std::string(field),
                   std::move(message)});
}

std::vector<Diagnostic> Diagnostics::only(Severity severity) const {
    std::vector<Diagnostic> out;
    std::copy_if(items_.begin(), items_.end(), std::back_inserter(out),
                 [severity](const Diagnostic& d) { return d.severity == severity; });
    return out;
}

const Diagnostic* Diagnostics::firstError() const noexcept {
    const auto it = std::find_if(items_.begin(), items_.end(),
                                 [](const Diagnostic& d) { return d.severity == Severity::Error; });
    return it == items_.end() ? nullptr : &*it;
}

std::string Diagnostics::toString() const {
    std::string out;
    for (const Diagnostic& d : items_) {
        out.append(out.empty() ? "" : "\n").append(d.toString());
    }
    return out;
}

ParseError::ParseError(Diagnostic diagnostic, std::string_view prefix)
    : Error(std::string(prefix) + diagnostic.toString()), diagnostic_(std::move(diagnostic)) {}

} // namespace e2d::core
