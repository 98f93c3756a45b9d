// SPDX-License-Identifier: MIT
#include <e2d/render/sprite_sheet.hpp>

#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/json_scan.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace e2d::render {
namespace {

// ordered_json keeps the hash format's frames in file order.
using Json = nlohmann::ordered_json;

// Sheets larger than this are not images any GPU loads; keeping coordinates below it also
// keeps every sum of two of them inside an int.
constexpr std::int64_t kMaxCoordinate = 1 << 20;

// A value as JSON text for a message: JSON escapes control characters and the replace handler
// turns ill-formed UTF-8 into U+FFFD, but DEL (0x7F) is valid JSON text and would reach the
// message raw; it is written \u007f like the other controls.
std::string dumpForMessage(const Json& value) {
    const std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        if (c == '\x7f') {
            out += "\\u007f";
        } else {
            out += c;
        }
    }
    return out;
}

class Reader {
public:
    explicit Reader(std::string_view sheetName) : sheet_(sheetName) {}

    // `path` is the JSON path of the value at fault; a problem of the text itself has a line
    // and column instead.
    [[noreturn]] void fail(std::string_view path, std::string what,
                           core::TextPosition at = {0, 0}) const {
        throw core::ParseError(core::Diagnostic{core::Severity::Error, core::printable(sheet_),
                                                at.line, at.column, std::string(path),
                                                std::move(what)},
                               "render::SpriteSheet: ");
    }

    static std::string describe(const Json& value) {
        return std::string(value.type_name()) + " " + core::shortened(dumpForMessage(value), 40);
    }

    const Json& member(const Json& object, std::string_view path, const char* key) const {
        if (!object.is_object()) {
            fail(path, "expected an object, got " + describe(object));
        }
        const auto it = object.find(key);
        if (it == object.end()) {
            fail(path, std::string("missing key \"") + key + "\"");
        }
        return *it;
    }

    const Json* optionalMember(const Json& object, const char* key) const {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    int integer(const Json& value, const std::string& path, std::int64_t min) const {
        std::int64_t result = 0;
        if (value.is_number_unsigned()) {
            const auto u = value.get<std::uint64_t>();
            result = u > static_cast<std::uint64_t>(kMaxCoordinate) ? kMaxCoordinate + 1
                                                                    : static_cast<std::int64_t>(u);
        } else if (value.is_number_integer()) {
            result = value.get<std::int64_t>();
        } else if (value.is_number_float()) {
            // TexturePacker writes whole numbers; accept 12.0 but not 12.5.
            const double d = value.get<double>();
            if (!(d >= static_cast<double>(-kMaxCoordinate) &&
                  d <= static_cast<double>(kMaxCoordinate)) ||
                d != static_cast<double>(static_cast<std::int64_t>(d))) {
                fail(path, "expected an integer, got " + describe(value));
            }
            result = static_cast<std::int64_t>(d);
        } else {
            fail(path, "expected an integer, got " + describe(value));
        }
        if (result < min || result > kMaxCoordinate) {
            fail(path, "expected an integer in [" + std::to_string(min) + ", " +
                           std::to_string(kMaxCoordinate) + "], got " + describe(value));
        }
        return static_cast<int>(result);
    }

    int intMember(const Json& object, const std::string& path, const char* key,
                  std::int64_t min) const {
        return integer(member(object, path, key), path + "." + key, min);
    }

    bool boolean(const Json& value, const std::string& path) const {
        if (!value.is_boolean()) {
            fail(path, "expected true or false, got " + describe(value));
        }
        return value.get<bool>();
    }

    float number(const Json& value, const std::string& path) const {
        if (!value.is_number()) {
            fail(path, "expected a number, got " + describe(value));
        }
        const double d = value.get<double>();
        if (!(d >= -1.0e6 && d <= 1.0e6)) {
            fail(path, "expected a number in [-1e6, 1e6], got " + describe(value));
        }
        return static_cast<float>(d);
    }

    PixelRect rect(const Json& object, const std::string& path, int minSize) const {
        PixelRect r;
        r.x = intMember(object, path, "x", 0);
        r.y = intMember(object, path, "y", 0);
        r.w = intMember(object, path, "w", minSize);
        r.h = intMember(object, path, "h", minSize);
        return r;
    }

    glm::ivec2 size(const Json& object, const std::string& path) const {
        return {intMember(object, path, "w", 1), intMember(object, path, "h", 1)};
    }

    SpriteFrame frame(const Json& object, const std::string& path, std::string name) const {
        if (!object.is_object()) {
            fail(path, "expected an object, got " + describe(object));
        }
        SpriteFrame f;
        f.name = std::move(name);
        const PixelRect display = rect(member(object, path, "frame"), path + ".frame", 1);
        if (const Json* v = optionalMember(object, "rotated")) {
            f.rotated = boolean(*v, path + ".rotated");
        }
        if (const Json* v = optionalMember(object, "trimmed")) {
            f.trimmed = boolean(*v, path + ".trimmed");
        }
        // TexturePacker writes a rotated frame's display size; in the image it is swapped.
        f.region = f.rotated ? PixelRect{display.x, display.y, display.h, display.w} : display;
        f.sourceSize = {display.w, display.h};
        if (const Json* v = optionalMember(object, "sourceSize")) {
            f.sourceSize = size(*v, path + ".sourceSize");
        }
        f.trimRect = {0, 0, display.w, display.h};
        if (const Json* v = optionalMember(object, "spriteSourceSize")) {
            const std::string p = path + ".spriteSourceSize";
            f.trimRect = rect(*v, p, 1);
            if (f.trimRect.x + f.trimRect.w > f.sourceSize.x ||
                f.trimRect.y + f.trimRect.h > f.sourceSize.y) {
                fail(p, "rectangle (x " + std::to_string(f.trimRect.x) + ", y " +
                            std::to_string(f.trimRect.y) + ", w " + std::to_string(f.trimRect.w) +
                            ", h " + std::to_string(f.trimRect.h) + ") lies outside sourceSize " +
                            std::to_string(f.sourceSize.x) + "x" + std::to_string(f.sourceSize.y));
            }
        }
        if (const Json* v = optionalMember(object, "pivot")) {
            const std::string p = path + ".pivot";
            f.pivot = {number(member(*v, p, "x"), p + ".x"), number(member(*v, p, "y"), p + ".y")};
        }
        return f;
    }

    void checkInside(const SpriteFrame& f, const std::string& path, glm::ivec2 image,
                     std::string_view what) const {
        const PixelRect& r = f.region;
        if (r.x + r.w > image.x || r.y + r.h > image.y) {
            fail(path, "frame \"" + core::printable(f.name) + "\" (x " + std::to_string(r.x) +
                           ", y " + std::to_string(r.y) + ", w " + std::to_string(r.w) + ", h " +
                           std::to_string(r.h) + (f.rotated ? ", rotated" : "") +
                           ") lies outside the " + std::to_string(image.x) + "x" +
                           std::to_string(image.y) + " image" + std::string(what));
        }
    }

private:
    std::string_view sheet_;
};

std::string hashPath(std::string_view name) {
    // Names are quoted (they hold dots and slashes); JSON's own escaping keeps them readable.
    return "frames[" + dumpForMessage(Json(std::string(name))) + "]";
}

// Splits a frame name into base, number and the rest: "run10.png" -> ("run", "10", ".png").
struct NumberedName {
    std::string_view digits;
    std::string_view rest;
};

bool splitNumbered(std::string_view name, std::string_view base, NumberedName& out) {
    if (name.size() <= base.size() || name.substr(0, base.size()) != base) {
        return false;
    }
    std::size_t end = base.size();
    while (end < name.size() && name[end] >= '0' && name[end] <= '9') {
        ++end;
    }
    if (end == base.size()) {
        return false;
    }
    const std::string_view rest = name.substr(end);
    if (!rest.empty() && rest.front() != '.') {
        return false;
    }
    out.digits = name.substr(base.size(), end - base.size());
    out.rest = rest;
    return true;
}

// Compares two digit strings by value, without converting (they can be arbitrarily long).
int compareNumbers(std::string_view a, std::string_view b) {
    const auto strip = [](std::string_view s) {
        const std::size_t first = s.find_first_not_of('0');
        return first == std::string_view::npos ? std::string_view{} : s.substr(first);
    };
    const std::string_view x = strip(a);
    const std::string_view y = strip(b);
    if (x.size() != y.size()) {
        return x.size() < y.size() ? -1 : 1;
    }
    const int c = x.compare(y);
    return c < 0 ? -1 : (c > 0 ? 1 : 0);
}

} // namespace

SpriteSheet SpriteSheet::fromFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    const core::TextFile file = core::readTextFile(path);
    if (!file.ok()) {
        Reader(name).fail("", "cannot read the file (" + file.error + ")");
    }
    return fromString(file.text, name, path.parent_path());
}

SpriteSheet SpriteSheet::fromString(std::string_view json, std::string_view name,
                                    const std::filesystem::path& imageFolder) {
    const Reader reader(name);
    // Printing or copying a value recurses once per level: bound the depth before parsing.
    if (const auto deep = core::findJsonNestingBeyond(json)) {
        const core::TextPosition at = core::positionOf(json, *deep);
        reader.fail("",
                    "arrays and objects nest deeper than " + std::to_string(core::kMaxJsonDepth) +
                        " levels; a sheet needs 4",
                    at);
    }
    Json root;
    try {
        root = Json::parse(json.begin(), json.end());
    } catch (const Json::parse_error& e) {
        const core::TextPosition at = core::positionOf(json, e.byte == 0 ? 0 : e.byte - 1);
        // nlohmann's text starts with "[json.exception.parse_error.101] parse error at line..."
        // and ends quoting the bytes it read, which need not be text.
        std::string what = e.what();
        const std::size_t reason = what.find(": ");
        if (reason != std::string::npos) {
            what = what.substr(reason + 2);
        }
        reader.fail("", "malformed JSON: " + core::printable(what), at);
    } catch (const Json::exception& e) {
        // A number too large for a double ("1e999") is reported as out_of_range, without a position.
        std::string what = e.what();
        const std::size_t reason = what.find("] ");
        reader.fail("", "malformed JSON: " + core::printable(reason == std::string::npos
                                                                 ? what
                                                                 : what.substr(reason + 2)));
    }

    SpriteSheet sheet;
    sheet.name_ = std::string(name);

    const Json& meta = reader.member(root, "", "meta");
    const Json& image = reader.member(meta, "meta", "image");
    if (!image.is_string() || image.get_ref<const std::string&>().empty()) {
        reader.fail("meta.image", "expected a non-empty string, got " + Reader::describe(image));
    }
    sheet.imagePath_ = imageFolder / std::filesystem::path(image.get<std::string>());
    sheet.imageSize_ = reader.size(reader.member(meta, "meta", "size"), "meta.size");

    const Json& frames = reader.member(root, "", "frames");
    const auto add = [&](SpriteFrame f, const std::string& path) {
        reader.checkInside(f, path + ".frame", sheet.imageSize_, " (meta.size)");
        const auto& size = sheet.imageSize_;
        const auto& r = f.region;
        const glm::vec2 pixels(size);
        f.uv = Rect{glm::vec2(static_cast<float>(r.x), static_cast<float>(r.y)) / pixels,
                    glm::vec2(static_cast<float>(r.w), static_cast<float>(r.h)) / pixels};
        if (!sheet.byName_.emplace(f.name, static_cast<int>(sheet.frames_.size())).second) {
            reader.fail(path, "duplicate frame name \"" + core::printable(f.name) + "\"");
        }
        sheet.frames_.push_back(std::move(f));
    };
    if (frames.is_object()) {
        sheet.frames_.reserve(frames.size());
        for (const auto& [key, value] : frames.items()) {
            const std::string path = hashPath(key);
            add(reader.frame(value, path, key), path);
        }
    } else if (frames.is_array()) {
        sheet.frames_.reserve(frames.size());
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const std::string path = "frames[" + std::to_string(i) + "]";
            const Json& filename = reader.member(frames[i], path, "filename");
            if (!filename.is_string()) {
                reader.fail(path + ".filename",
                            "expected a string, got " + Reader::describe(filename));
            }
            add(reader.frame(frames[i], path, filename.get<std::string>()), path);
        }
    } else {
        reader.fail("frames", "expected an object (hash format) or an array (array format), got " +
                                  Reader::describe(frames));
    }
    return sheet;
}

const SpriteFrame* SpriteSheet::find(std::string_view name) const {
    const auto it = byName_.find(std::string(name));
    return it == byName_.end() ? nullptr : &frames_[static_cast<std::size_t>(it->second)];
}

const SpriteFrame& SpriteSheet::frame(std::string_view name) const {
    if (const SpriteFrame* f = find(name)) {
        return *f;
    }
    throw core::Error("render::SpriteSheet::frame(): '" + name_ + "' has no frame \"" +
                      core::printable(name) + "\"");
}

std::vector<int> SpriteSheet::animationFrames(std::string_view baseName) const {
    struct Entry {
        int index;
        NumberedName parts;
    };
    std::vector<Entry> entries;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        NumberedName parts;
        if (splitNumbered(frames_[i].name, baseName, parts)) {
            entries.push_back({static_cast<int>(i), parts});
        }
    }
    std::sort(entries.begin(), entries.end(), [this](const Entry& a, const Entry& b) {
        if (const int c = compareNumbers(a.parts.digits, b.parts.digits); c != 0) {
            return c < 0;
        }
        if (a.parts.digits.size() != b.parts.digits.size()) {
            return a.parts.digits.size() < b.parts.digits.size();
        }
        return frames_[static_cast<std::size_t>(a.index)].name <
               frames_[static_cast<std::size_t>(b.index)].name;
    });
    std::vector<int> result;
    result.reserve(entries.size());
    for (const Entry& e : entries) {
        result.push_back(e.index);
    }
    return result;
}

void SpriteSheet::checkImageSize(glm::ivec2 actualSize) const {
    const Reader reader(name_);
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        reader.checkInside(frames_[i], hashPath(frames_[i].name) + ".frame", actualSize,
                           " loaded from '" + imagePath_.string() + "' (meta.size says " +
                               std::to_string(imageSize_.x) + "x" + std::to_string(imageSize_.y) +
                               ")");
    }
}

} // namespace e2d::render
