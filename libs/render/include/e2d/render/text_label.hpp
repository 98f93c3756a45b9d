// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/text.hpp>
#include <e2d/render/text_renderer.hpp>

#include <filesystem>
#include <string>

namespace e2d::render {

/// How a TextLabel starts.
struct TextLabelDef {
    /// UTF-8 text; '\n' breaks lines. Default "".
    std::string text{};
    /// Font file; an unreadable one falls back to the default font (see TextRenderer::font()).
    /// Default kDefaultFontPath.
    std::filesystem::path fontPath = kDefaultFontPath;
    /// Font size, pixels, in [1, 1024]. Default 32.
    int pixelSize = 32;
    /// Alignment about the object's position, kerning, line spacing. Default left, top.
    TextStyle style{};
    /// Multiplies the glyphs' coverage. Default opaque white.
    Color color{};
    /// World units per font pixel before the object's scale, each > 0 and finite. Default (1, 1).
    glm::vec2 scale{1.0f, 1.0f};
    /// Camera space (HUD): the object's position is read as camera units. Default false.
    bool hud = false;
    /// Added to the object's world z. Default 0.
    float zOffset = 0.0f;
    /// Default true.
    bool visible = true;
};

/// Text drawn at its game object every frame: the anchor at the object's world position, its
/// z, rotation and scale following the object's world transform (parent chain included), laid
/// out with the RenderSystem's TextRenderer and batched with the sprites.
class TextLabel : public core::Component, private RenderHook {
public:
    /// Throws core::Error naming an invalid field ("render::TextLabel: pixelSize must be in
    /// [1, 1024], got 0").
    explicit TextLabel(const TextLabelDef& def = {});
    ~TextLabel() override;

    void setText(std::string text) { def_.text = std::move(text); }
    [[nodiscard]] const std::string& text() const noexcept { return def_.text; }
    void setColor(Color color) noexcept { def_.color = color; }
    /// Alignment, kerning and line spacing from the next frame on. Throws core::Error for a
    /// lineSpacing that is not > 0 and finite ("render::TextLabel::setStyle(): ...").
    void setStyle(const TextStyle& style);
    /// Only the alignment (the text demo switches it with the keyboard).
    void setAlignment(HorizontalAlign horizontal, VerticalAlign vertical) noexcept {
        def_.style.horizontal = horizontal;
        def_.style.vertical = vertical;
    }
    void setVisible(bool visible) noexcept { def_.visible = visible; }
    [[nodiscard]] const TextLabelDef& def() const noexcept { return def_; }
    /// The font in use; null before onInitialize or when no font could be read.
    [[nodiscard]] Font* font() const noexcept { return font_; }
    /// The layout of the last frame drawn (font pixels relative to the anchor).
    [[nodiscard]] const TextLayout& layout() const noexcept { return layout_; }

    void onInitialize() override;
    void onTerminate() override;

private:
    void beforeRender(Renderer& renderer) override;
    void detach() noexcept;

    TextLabelDef def_;
    RenderSystem* system_ = nullptr;
    Font* font_ = nullptr;
    TextLayout layout_;
};

} // namespace e2d::render
