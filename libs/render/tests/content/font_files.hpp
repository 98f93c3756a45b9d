// SPDX-License-Identifier: MIT
// Damaged TrueType fonts for the font tests, made from the default font (DejaVu Sans) by
// rewriting its table directory: tables reordered, dropped, a glyph's outline broken, the file
// cut short. Nothing here is committed; every test writes its own file.
#pragma once

#include <e2d/render/font.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace e2d::render::test {

class SfntFile {
public:
    struct Table {
        std::string tag;
        std::vector<char> data;
    };

    SfntFile() : SfntFile(kDefaultFontPath) {}
    explicit SfntFile(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                      std::istreambuf_iterator<char>()};
        if (bytes.size() < 12) {
            throw std::runtime_error("not a font: " + path.string());
        }
        version_.assign(bytes.begin(), bytes.begin() + 4);
        const std::uint32_t count = read(bytes, 4, 2);
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::size_t entry = 12 + 16 * static_cast<std::size_t>(i);
            const std::uint32_t offset = read(bytes, entry + 8, 4);
            const std::uint32_t length = read(bytes, entry + 12, 4);
            tables_.push_back(
                {std::string(bytes.begin() + static_cast<std::ptrdiff_t>(entry),
                             bytes.begin() + static_cast<std::ptrdiff_t>(entry + 4)),
                 std::vector<char>(bytes.begin() + offset, bytes.begin() + offset + length)});
        }
    }

    Table& table(const std::string& tag) {
        for (Table& t : tables_) {
            if (t.tag == tag) {
                return t;
            }
        }
        throw std::runtime_error("no table " + tag);
    }

    void drop(const std::string& tag) {
        std::erase_if(tables_, [&](const Table& t) { return t.tag == tag; });
    }

    // Puts `tag`'s data at the end of the file (the directory keeps its sorted order).
    void moveToEnd(const std::string& tag) {
        Table moved = table(tag);
        drop(tag);
        tables_.push_back(std::move(moved));
    }

    // Breaks glyph `index`'s outline: it claims 30 000 contours, more than its data holds.
    void breakGlyph(unsigned index) {
        const Table& head = table("head");
        const bool longOffsets = read(head.data, 50, 2) != 0;
        const Table& loca = table("loca");
        const std::size_t offset =
            longOffsets ? read(loca.data, 4 * static_cast<std::size_t>(index), 4)
                        : 2 * read(loca.data, 2 * static_cast<std::size_t>(index), 2);
        std::vector<char>& glyf = table("glyf").data;
        glyf[offset] = static_cast<char>(30000 >> 8);
        glyf[offset + 1] = static_cast<char>(30000 & 0xff);
    }

    // The file, cut to `fraction` of its size.
    [[nodiscard]] std::vector<char> bytes(double fraction = 1.0) const {
        std::vector<char> out(version_);
        write(out, static_cast<std::uint32_t>(tables_.size()), 2);
        out.resize(12, 0); // searchRange and friends: FreeType does not need them
        std::vector<const Table*> sorted;
        for (const Table& t : tables_) {
            sorted.push_back(&t);
        }
        std::sort(sorted.begin(), sorted.end(),
                  [](const Table* a, const Table* b) { return a->tag < b->tag; });
        std::uint32_t offset = static_cast<std::uint32_t>(12 + 16 * tables_.size());
        std::vector<std::uint32_t> offsets;
        for (const Table& t : tables_) {
            offsets.push_back(offset);
            offset += static_cast<std::uint32_t>((t.data.size() + 3) & ~std::size_t{3});
        }
        for (const Table* t : sorted) {
            out.insert(out.end(), t->tag.begin(), t->tag.end());
            write(out, 0, 4); // checksum: FreeType does not check it
            write(out, offsets[static_cast<std::size_t>(t - tables_.data())], 4);
            write(out, static_cast<std::uint32_t>(t->data.size()), 4);
        }
        for (const Table& t : tables_) {
            out.insert(out.end(), t.data.begin(), t.data.end());
            out.resize((out.size() + 3) & ~std::size_t{3}, 0);
        }
        out.resize(static_cast<std::size_t>(static_cast<double>(out.size()) * fraction));
        return out;
    }

    void save(const std::filesystem::path& path, double fraction = 1.0) const {
        const std::vector<char> data = bytes(fraction);
        std::ofstream(path, std::ios::binary | std::ios::trunc)
            .write(data.data(), static_cast<std::streamsize>(data.size()));
    }

private:
    static std::uint32_t read(const std::vector<char>& b, std::size_t at, int n) {
        std::uint32_t v = 0;
        for (int i = 0; i < n; ++i) {
            v = (v << 8) | static_cast<std::uint8_t>(b[at + static_cast<std::size_t>(i)]);
        }
        return v;
    }
    static void write(std::vector<char>& out, std::uint32_t v, int n) {
        for (int i = n - 1; i >= 0; --i) {
            out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
        }
    }

    std::vector<char> version_;
    std::vector<Table> tables_;
};

// The default font with its glyph outlines last, cut at 60 %: it opens, and every glyph is
// empty (FreeType drops a table that ends past the end of the file).
inline std::filesystem::path writeCutShortFont(const std::string& name) {
    const auto path = std::filesystem::temp_directory_path() / name;
    SfntFile font;
    font.moveToEnd("glyf");
    font.save(path, 0.6);
    return path;
}

} // namespace e2d::render::test
