// SPDX-License-Identifier: MIT
#include <e2d/render/text.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/utf8.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace e2d::render {
namespace {

struct Pending {
    const Glyph* glyph;
    float penX;
    int line;
    char32_t codePoint;
};

void join(TextRect& into, const TextRect& r) {
    into.min = glm::min(into.min, r.min);
    into.max = glm::max(into.max, r.max);
}

} // namespace

TextLayout layoutText(Font& font, std::string_view utf8, const TextStyle& style) {
    if (!std::isfinite(style.lineSpacing) || style.lineSpacing <= 0.0f) {
        throw core::Error("render::layoutText(): lineSpacing must be finite and > 0, got " +
                          std::to_string(style.lineSpacing));
    }
    TextLayout layout;
    std::vector<Pending> pending;
    pending.reserve(utf8.size());
    std::vector<float> widths(1, 0.0f);

    // Pass 1: pen positions per line; glyphs may still grow the atlas.
    float pen = 0.0f;
    const Glyph* previous = nullptr;
    const float spaceAdvance = font.glyph(U' ').advance;
    std::size_t pos = 0;
    while (pos < utf8.size()) {
        const char32_t c = core::decodeUtf8(utf8, pos);
        if (c == U'\n') {
            widths.back() = pen;
            widths.push_back(0.0f);
            pen = 0.0f;
            previous = nullptr;
            continue;
        }
        if (c == U'\r') {
            // "\r\n" is one break; a lone '\r' is one too.
            if (pos < utf8.size() && utf8[pos] == '\n') {
                continue;
            }
            widths.back() = pen;
            widths.push_back(0.0f);
            pen = 0.0f;
            previous = nullptr;
            continue;
        }
        if (c == U'\t') {
            const float stop = 4.0f * spaceAdvance;
            pen = stop > 0.0f ? (std::floor(pen / stop) + 1.0f) * stop : pen;
            previous = nullptr;
            continue;
        }
        if (c < 0x20 || (c >= 0x7F && c < 0xA0)) {
            continue;
        }
        const Glyph& g = font.glyph(c);
        if (style.kerning && previous != nullptr) {
            pen += font.kerning(*previous, g);
        }
        pending.push_back({&g, pen, static_cast<int>(widths.size()) - 1, c});
        pen += g.advance;
        previous = &g;
    }
    widths.back() = pen;

    // Pass 2: alignment and quads, with the atlas at its final size.
    const int lines = static_cast<int>(widths.size());
    const float step = std::round(font.lineHeight() * style.lineSpacing);
    const float ascender = std::round(font.ascender());
    const float descender = std::round(font.descender());
    const float height = ascender - descender + step * static_cast<float>(lines - 1);
    float top = 0.0f;
    switch (style.vertical) {
    case VerticalAlign::Top:
        top = 0.0f;
        break;
    case VerticalAlign::Center:
        top = std::round(height * 0.5f);
        break;
    case VerticalAlign::Bottom:
        top = height;
        break;
    }
    std::vector<float> lineStart(widths.size());
    for (std::size_t i = 0; i < widths.size(); ++i) {
        switch (style.horizontal) {
        case HorizontalAlign::Left:
            lineStart[i] = 0.0f;
            break;
        case HorizontalAlign::Center:
            lineStart[i] = -std::round(widths[i] * 0.5f);
            break;
        case HorizontalAlign::Right:
            lineStart[i] = -std::round(widths[i]);
            break;
        }
    }

    layout.lineCount = lines;
    layout.lineWidths = widths;
    layout.box.min = {std::numeric_limits<float>::max(), top - height};
    layout.box.max = {std::numeric_limits<float>::lowest(), top};
    for (std::size_t i = 0; i < widths.size(); ++i) {
        layout.box.min.x = std::min(layout.box.min.x, lineStart[i]);
        layout.box.max.x = std::max(layout.box.max.x, lineStart[i] + widths[i]);
    }
    layout.bounds = layout.box;

    layout.quads.reserve(pending.size());
    for (const Pending& p : pending) {
        const Glyph& g = *p.glyph;
        if (g.atlasRect.w == 0 || g.atlasRect.h == 0) {
            continue;
        }
        const float baseline = top - ascender - step * static_cast<float>(p.line);
        GlyphQuad q;
        q.rect.min = {lineStart[static_cast<std::size_t>(p.line)] + std::round(p.penX) +
                          static_cast<float>(g.bearing.x),
                      baseline + static_cast<float>(g.bearing.y - g.atlasRect.h)};
        q.rect.max = q.rect.min + glm::vec2(static_cast<float>(g.atlasRect.w),
                                            static_cast<float>(g.atlasRect.h));
        q.atlasRect = g.atlasRect;
        q.codePoint = p.codePoint;
        q.missing = g.missing;
        join(layout.bounds, q.rect);
        layout.quads.push_back(q);
    }
    return layout;
}

} // namespace e2d::render
