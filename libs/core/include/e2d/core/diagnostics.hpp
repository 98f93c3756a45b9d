// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

/// What every e2d parser reports (the `key = value` config reader, input bindings, gamepad
/// mappings and scripts, sprite sheets, the validation's scenarios): one shape, one formatter.
namespace e2d::core {

/// How bad a problem is: an error refuses what it is about, a warning keeps it.
enum class Severity { Warning, Error };

/// One problem found in a text or a file.
struct Diagnostic {
    Severity severity = Severity::Error;
    /// The file's path or the name given for the text; printable (core::printable).
    std::string file;
    /// 1-based line, 0 when the problem is not tied to a line (a missing file, a JSON value).
    int line = 0;
    /// 1-based column (byte), 0 when unknown.
    int column = 0;
    /// What the problem is about when the place is not a line: a key (`"windowWidth"`), a JSON
    /// path (`"frames[3].frame.w"`); empty when there is none.
    std::string field;
    /// What is wrong: `"expected an integer, got 'abc'"`.
    std::string message;

    /// `"file:line:column: field: message"`, leaving out what is absent:
    /// `"game.cfg:12: windowWidth: expected an integer, got 'abc'"`, `"pads.txt:3: ..."`,
    /// `"sheet.json: frames[0].frame.w: expected an integer ..."`; a text without a file name
    /// gives its place in words: `"line 3, column 7: ..."`.
    [[nodiscard]] std::string toString() const;
};

/// The problems one parse found, in the order found.
class Diagnostics {
public:
    /// Adds a problem (its fields as in Diagnostic).
    void add(Diagnostic diagnostic);
    void error(std::string_view file, int line, std::string message, std::string_view field = {});
    void warning(std::string_view file, int line, std::string message, std::string_view field = {});

    /// No errors (warnings allowed): what was parsed may be used.
    [[nodiscard]] bool ok() const noexcept { return errors_ == 0; }
    [[nodiscard]] bool empty() const noexcept { return items_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }
    [[nodiscard]] int errorCount() const noexcept { return errors_; }
    [[nodiscard]] int warningCount() const noexcept {
        return static_cast<int>(items_.size()) - errors_;
    }

    [[nodiscard]] const Diagnostic& operator[](std::size_t i) const { return items_[i]; }
    [[nodiscard]] auto begin() const noexcept { return items_.begin(); }
    [[nodiscard]] auto end() const noexcept { return items_.end(); }
    /// The errors alone, and the warnings alone, in order.
    [[nodiscard]] std::vector<Diagnostic> errors() const { return only(Severity::Error); }
    [[nodiscard]] std::vector<Diagnostic> warnings() const { return only(Severity::Warning); }
    [[nodiscard]] std::vector<Diagnostic> only(Severity severity) const;
    /// The first error, or nullptr.
    [[nodiscard]] const Diagnostic* firstError() const noexcept;
    /// Every problem's toString(), one per line (no newline after the last).
    [[nodiscard]] std::string toString() const;

private:
    std::vector<Diagnostic> items_;
    int errors_ = 0;
};

/// The core::Error a parser that refuses its input as a whole throws: what() is the
/// diagnostic's toString() after `prefix` (the function, when it adds something:
/// `"render::SpriteSheet: "`), and the diagnostic itself is kept for a caller that wants the
/// line or the field.
class ParseError : public Error {
public:
    explicit ParseError(Diagnostic diagnostic, std::string_view prefix = {});
    [[nodiscard]] const Diagnostic& diagnostic() const noexcept { return diagnostic_; }

private:
    Diagnostic diagnostic_;
};

} // namespace e2d::core
