// SPDX-License-Identifier: MIT
// e2d_image_check IMAGE.png RULE...: checks a screenshot against region rules, prints what it
// measured for each rule and exits 0 when every rule holds, 1 when one fails, 2 for bad usage
// or an unreadable image. Rules (one argument each; regions in pixels from the top-left):
//   size:W,H                   the image is W x H pixels
//   colour:X,Y,W,H:R,G,B:T:P   at least P % of the region's pixels have every channel within T
//                              of R,G,B
//   ink:X,Y,W,H[:P]            at least P % (default 0.5) of the region's pixels differ by more
//                              than 40 in some channel from the region's commonest colour
//   empty:X,Y,W,H              fewer than 0.1 % of them do
// `--self-test` draws an image with known regions, writes it, and checks rules that must pass
// and rules that must fail against it.
#include <e2d/core/error.hpp>
#include <e2d/render/image.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace {

using e2d::render::Image;

constexpr int kInkDistance = 40;

struct Region {
    int x = 0, y = 0, w = 0, h = 0;
};

std::vector<std::string_view> split(std::string_view text, char sep) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(sep, start);
        out.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos
                                                                       : end - start));
        if (end == std::string_view::npos) {
            return out;
        }
        start = end + 1;
    }
}

double number(std::string_view text, std::string_view rule) {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size()) {
        throw e2d::core::Error("rule '" + std::string(rule) + "': '" + std::string(text) +
                               "' is not a number");
    }
    return value;
}

std::vector<int> integers(std::string_view text, std::size_t count, std::string_view rule) {
    const std::vector<std::string_view> parts = split(text, ',');
    if (parts.size() != count) {
        throw e2d::core::Error("rule '" + std::string(rule) + "': expected " +
                               std::to_string(count) + " comma-separated numbers in '" +
                               std::string(text) + "'");
    }
    std::vector<int> out;
    for (std::string_view p : parts) {
        out.push_back(static_cast<int>(number(p, rule)));
    }
    return out;
}

Region region(std::string_view text, std::string_view rule, const Image& image) {
    const std::vector<int> v = integers(text, 4, rule);
    const Region r{v[0], v[1], v[2], v[3]};
    if (r.w <= 0 || r.h <= 0 || r.x < 0 || r.y < 0 || r.x + r.w > image.width ||
        r.y + r.h > image.height) {
        throw e2d::core::Error("rule '" + std::string(rule) + "': region outside the " +
                               std::to_string(image.width) + " x " + std::to_string(image.height) +
                               " image");
    }
    return r;
}

const std::uint8_t* pixel(const Image& image, int x, int y) { return image.at(x, y); }

int distance(const std::uint8_t* p, int r, int g, int b) {
    return std::max({std::abs(p[0] - r), std::abs(p[1] - g), std::abs(p[2] - b)});
}

/// Percentage of the region's pixels within `tolerance` of the colour.
double colourShare(const Image& image, Region reg, int r, int g, int b, int tolerance) {
    long count = 0;
    for (int y = reg.y; y < reg.y + reg.h; ++y) {
        for (int x = reg.x; x < reg.x + reg.w; ++x) {
            count += distance(pixel(image, x, y), r, g, b) <= tolerance ? 1 : 0;
        }
    }
    return 100.0 * static_cast<double>(count) / (static_cast<double>(reg.w) * reg.h);
}

/// Percentage of the region's pixels farther than kInkDistance from its commonest colour.
double inkShare(const Image& image, Region reg) {
    std::map<std::uint32_t, long> histogram;
    for (int y = reg.y; y < reg.y + reg.h; ++y) {
        for (int x = reg.x; x < reg.x + reg.w; ++x) {
            const std::uint8_t* p = pixel(image, x, y);
            ++histogram[(std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2]];
        }
    }
    const auto common =
        std::max_element(histogram.begin(), histogram.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    const int r = static_cast<int>((common->first >> 16) & 0xFF);
    const int g = static_cast<int>((common->first >> 8) & 0xFF);
    const int b = static_cast<int>(common->first & 0xFF);
    return 100.0 - colourShare(image, reg, r, g, b, kInkDistance);
}

/// Checks one rule; prints the measurement; returns whether it holds.
bool check(const Image& image, std::string_view rule) {
    const std::vector<std::string_view> parts = split(rule, ':');
    const std::string_view kind = parts[0];
    char line[256];
    bool ok = false;
    if (kind == "size" && parts.size() == 2) {
        const std::vector<int> s = integers(parts[1], 2, rule);
        ok = image.width == s[0] && image.height == s[1];
        std::snprintf(line, sizeof line, "image is %d x %d", image.width, image.height);
    } else if (kind == "colour" && parts.size() == 5) {
        const Region reg = region(parts[1], rule, image);
        const std::vector<int> c = integers(parts[2], 3, rule);
        const double tolerance = number(parts[3], rule);
        const double wanted = number(parts[4], rule);
        const double share = colourShare(image, reg, c[0], c[1], c[2], static_cast<int>(tolerance));
        ok = share >= wanted;
        std::snprintf(line, sizeof line,
                      "%.2f %% of the region within %g of (%d, %d, %d), wanted >= %g %%", share,
                      tolerance, c[0], c[1], c[2], wanted);
    } else if (kind == "ink" && (parts.size() == 2 || parts.size() == 3)) {
        const Region reg = region(parts[1], rule, image);
        const double wanted = parts.size() == 3 ? number(parts[2], rule) : 0.5;
        const double share = inkShare(image, reg);
        ok = share >= wanted;
        std::snprintf(line, sizeof line, "%.2f %% ink, wanted >= %g %%", share, wanted);
    } else if (kind == "empty" && parts.size() == 2) {
        const Region reg = region(parts[1], rule, image);
        const double share = inkShare(image, reg);
        ok = share < 0.1;
        std::snprintf(line, sizeof line, "%.2f %% ink, wanted < 0.1 %%", share);
    } else {
        throw e2d::core::Error(
            "unknown rule '" + std::string(rule) +
            "' (size:W,H, colour:X,Y,W,H:R,G,B:T:P, ink:X,Y,W,H[:P], empty:X,Y,W,H)");
    }
    std::printf("%s %s: %s\n", ok ? "ok  " : "FAIL", std::string(rule).c_str(), line);
    return ok;
}

int selfTest() {
    // 100 x 50, black; a red 20 x 10 block at (10, 5); a white diagonal in (60, 0, 40, 40).
    Image image;
    image.width = 100;
    image.height = 50;
    image.pixels.assign(100 * 50 * 4, 0);
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) {
        image.pixels[i] = 255;
    }
    const auto set = [&](int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        std::uint8_t* p = image.pixels.data() +
                          (static_cast<std::size_t>(y) * 100 + static_cast<std::size_t>(x)) * 4;
        p[0] = r;
        p[1] = g;
        p[2] = b;
    };
    for (int y = 5; y < 15; ++y) {
        for (int x = 10; x < 30; ++x) {
            set(x, y, 250, 10, 10);
        }
    }
    for (int i = 0; i < 40; ++i) {
        set(60 + i, i, 255, 255, 255);
    }
    e2d::render::writePng(image, "image_check_self_test.png");
    const Image read = e2d::render::loadImage("image_check_self_test.png");
    const std::vector<std::string> pass{"size:100,50", "colour:10,5,20,10:255,0,0:20:100",
                                        "colour:0,0,40,20:255,0,0:20:25", "ink:60,0,40,40:2",
                                        "empty:0,20,50,30"};
    const std::vector<std::string> fail{"size:50,100",
                                        "colour:0,0,40,20:255,0,0:20:26",
                                        "colour:10,5,20,10:0,0,255:40:1",
                                        "ink:60,0,40,40:3",
                                        "empty:60,0,40,40",
                                        "ink:0,20,50,30"};
    int wrong = 0;
    for (const std::string& rule : pass) {
        wrong += check(read, rule) ? 0 : 1;
    }
    std::printf("-- the next rules must fail:\n");
    for (const std::string& rule : fail) {
        wrong += check(read, rule) ? 1 : 0;
    }
    std::printf("self test: %s\n", wrong == 0 ? "ok" : "WRONG");
    return wrong == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 2 && std::string_view(argv[1]) == "--self-test") {
            return selfTest();
        }
        if (argc < 3) {
            std::fprintf(
                stderr,
                "usage: e2d_image_check IMAGE.png RULE... (see apps/tools/image_check.cpp)\n");
            return 2;
        }
        const Image image = e2d::render::loadImage(argv[1]);
        bool ok = true;
        for (int i = 2; i < argc; ++i) {
            ok = check(image, argv[i]) && ok;
        }
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "e2d_image_check: %s\n", e.what());
        return 2;
    }
}
