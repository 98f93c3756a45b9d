// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/render/font.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/text.hpp>
#include <e2d/render/types.hpp>

#include <filesystem>
#include <string>

namespace e2d::render {

/// How a TextLabel starts.
struct TextLabelDef {
    /// UTF-8 text; '\n' separates lines. Default "".
    std::string text;
    /// Font file, opened through the RenderSystem's TextRenderer (a bad file is reported once
    /// and the default font stands in). Default kDefaultFontPath (DejaVu Sans).
    std::filesystem::path fontPath = kDefaultFontPath;
    /// Font size, pixels, in [1, 1024]. Default 32.
    int pixelSize = 32;
    /// Alignment about the object's position, kerning, line spacing. Default left, top.
    TextStyle style{};
    /// Multiplies the glyphs. Default opaque white.
    Color color{};
    /// Camera space (HUD): the object's position is read as camera units. Default false.
    bool hud = false;
    /// Added to the object's world z. Default 0.
    float zOffset = 0.0f;
};

/// The seed's TextLabel: text drawn at its game object, following the object's world position,
/// z, orientation and scale (world units per font pixel; scale 1: one unit per pixel) every
/// frame. The layout is redone only when the text, style or font changes.
class TextLabel : public core::Component, public RenderHook {
public:
    /// Throws core::Error naming an invalid field (pixelSize out of range, lineSpacing not
    /// finite and > 0, zOffset not finite).
    explicit TextLabel(const TextLabelDef& def = {});
    ~TextLabel() override;

    [[nodiscard]] const TextLabelDef& def() const noexcept { return def_; }
    [[nodiscard]] const std::string& text() const noexcept { return def_.text; }
    void setText(std::string text);
    /// Throws core::Error as the constructor for an invalid style.
    void setStyle(const TextStyle& style);
    void setAlignment(HorizontalAlign horizontal, VerticalAlign vertical);
    void setColor(Color color) noexcept { def_.color = color; }
    void setVisible(bool visible) noexcept { visible_ = visible; }
    [[nodiscard]] bool visible() const noexcept { return visible_; }
    /// The last layout drawn, font pixels relative to the anchor (empty before the first frame
    /// or when no font could be opened).
    [[nodiscard]] const TextLayout& layout() const noexcept { return layout_; }

    void onInitialize() override;
    void onTerminate() override;
    void beforeRender(Renderer& renderer) override;

private:
    TextLabelDef def_;
    RenderSystem* system_ = nullptr;
    Font* font_ = nullptr;
    TextLayout layout_;
    bool dirty_ = true;
    bool visible_ = true;
};

} // namespace e2d::render
