// SPDX-License-Identifier: MIT
#include <e2d/render/image.hpp>

#include <e2d/core/error.hpp>

#include <FreeImage.h>

#include <cstring>
#include <string>
#include <system_error>

namespace e2d::render {

namespace {

// FreeImage reports why a load failed only through its process-wide output-message callback,
// which takes no user pointer. While a call is in flight the callback appends to the string
// of the capture on this thread (set and restored by MessageCapture, nothing kept after).
thread_local std::string* t_freeImageMessage = nullptr;

void onFreeImageMessage(FREE_IMAGE_FORMAT format, const char* message) {
    if (t_freeImageMessage == nullptr || message == nullptr) {
        return;
    }
    if (!t_freeImageMessage->empty()) {
        t_freeImageMessage->append("; ");
    }
    const char* name = format != FIF_UNKNOWN ? FreeImage_GetFormatFromFIF(format) : nullptr;
    if (name != nullptr) {
        t_freeImageMessage->append(name).append(": ");
    }
    t_freeImageMessage->append(message);
}

class MessageCapture {
public:
    MessageCapture() : previous_(t_freeImageMessage) {
        FreeImage_SetOutputMessage(&onFreeImageMessage);
        t_freeImageMessage = &text_;
    }
    ~MessageCapture() { t_freeImageMessage = previous_; }
    MessageCapture(const MessageCapture&) = delete;
    MessageCapture& operator=(const MessageCapture&) = delete;
    [[nodiscard]] std::string reason(const char* fallback) const {
        return text_.empty() ? fallback : text_;
    }

private:
    std::string text_;
    std::string* previous_;
};

std::string formatName(FREE_IMAGE_FORMAT format) {
    const char* name = FreeImage_GetFormatFromFIF(format);
    return name != nullptr ? name : "unknown";
}

const char* imageTypeName(FREE_IMAGE_TYPE type) {
    switch (type) {
    case FIT_BITMAP:
        return "standard bitmap";
    case FIT_UINT16:
        return "16-bit unsigned";
    case FIT_INT16:
        return "16-bit signed";
    case FIT_UINT32:
        return "32-bit unsigned";
    case FIT_INT32:
        return "32-bit signed";
    case FIT_FLOAT:
        return "32-bit float";
    case FIT_DOUBLE:
        return "64-bit float";
    case FIT_COMPLEX:
        return "complex";
    case FIT_RGB16:
        return "16-bit RGB";
    case FIT_RGBA16:
        return "16-bit RGBA";
    case FIT_RGBF:
        return "float RGB";
    case FIT_RGBAF:
        return "float RGBA";
    default:
        return "unknown type";
    }
}

// Most 32-bit BMPs are BI_RGB, whose fourth byte is padding that writers leave 0; FreeImage
// reads it as alpha. As image viewers do, an image whose alpha is 0 everywhere is opaque.
void opaqueIfAlphaIsPadding(Image& image) {
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) {
        if (image.pixels[i] != 0) {
            return;
        }
    }
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) {
        image.pixels[i] = 255;
    }
}

struct Bitmap {
    FIBITMAP* bitmap = nullptr;
    explicit Bitmap(FIBITMAP* b) : bitmap(b) {}
    ~Bitmap() {
        if (bitmap != nullptr) {
            FreeImage_Unload(bitmap);
        }
    }
    Bitmap(const Bitmap&) = delete;
    Bitmap& operator=(const Bitmap&) = delete;
};

} // namespace

Image loadImage(const std::filesystem::path& path) {
    const std::string file = path.string();
    auto failFile = [&](const std::string& reason) -> void {
        throw core::Error("render::loadImage(): " + file + ": " + reason);
    };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        failFile(std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
    }
    MessageCapture capture;
    FREE_IMAGE_FORMAT content = FreeImage_GetFileType(file.c_str(), 0);
    if (content == FIF_UNKNOWN) {
        failFile(capture.reason("FreeImage does not recognise the image format"));
    }
    FREE_IMAGE_FORMAT named = FreeImage_GetFIFFromFilename(file.c_str());
    if (named != FIF_UNKNOWN && named != content && !(named == FIF_TIFF && content == FIF_TIFF)) {
        failFile("the content is " + formatName(content) + " but the extension says " +
                 formatName(named));
    }
    if (FreeImage_FIFSupportsReading(content) == FALSE) {
        failFile("FreeImage cannot read " + formatName(content) + " files");
    }
    // A camera's JPEG stores its pixels as the sensor saw them and says in EXIF how to turn
    // them upright; image viewers do turn them.
    Bitmap loaded(FreeImage_Load(content, file.c_str(), content == FIF_JPEG ? JPEG_EXIFROTATE : 0));
    if (loaded.bitmap == nullptr) {
        failFile(
            capture.reason("FreeImage_Load() failed without a reason (corrupt or truncated?)"));
    }
    if (!capture.reason("").empty()) {
        // libpng and libjpeg report truncated data as a warning and hand back a partial image.
        failFile(capture.reason(""));
    }
    unsigned width = FreeImage_GetWidth(loaded.bitmap);
    unsigned height = FreeImage_GetHeight(loaded.bitmap);
    if (width == 0 || height == 0) {
        failFile("the image is " + std::to_string(width) + " x " + std::to_string(height) +
                 " pixels");
    }
    // FreeImage converts 16-bit greyscale to 32 bits only by way of 8 bits (the high byte).
    Bitmap grey(FreeImage_GetImageType(loaded.bitmap) == FIT_UINT16
                    ? FreeImage_ConvertTo8Bits(loaded.bitmap)
                    : nullptr);
    Bitmap rgba(FreeImage_ConvertTo32Bits(grey.bitmap != nullptr ? grey.bitmap : loaded.bitmap));
    if (rgba.bitmap == nullptr) {
        const std::string fallback = "FreeImage could not convert it to 32-bit RGBA (" +
                                     std::to_string(FreeImage_GetBPP(loaded.bitmap)) +
                                     " bits per pixel, " +
                                     imageTypeName(FreeImage_GetImageType(loaded.bitmap)) + ")";
        failFile(capture.reason(fallback.c_str()));
    }
    Image image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.pixels.resize(static_cast<std::size_t>(width) * height * 4);
    // FreeImage rows are bottom-up and BGRA (on little-endian machines): one place converts.
    for (unsigned y = 0; y < height; ++y) {
        const BYTE* src = FreeImage_GetScanLine(rgba.bitmap, static_cast<int>(y));
        std::uint8_t* dst =
            image.pixels.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
        for (unsigned x = 0; x < width; ++x) {
            dst[x * 4 + 0] = src[x * 4 + FI_RGBA_RED];
            dst[x * 4 + 1] = src[x * 4 + FI_RGBA_GREEN];
            dst[x * 4 + 2] = src[x * 4 + FI_RGBA_BLUE];
            dst[x * 4 + 3] = src[x * 4 + FI_RGBA_ALPHA];
        }
    }
    if (content == FIF_BMP && FreeImage_GetBPP(loaded.bitmap) == 32) {
        opaqueIfAlphaIsPadding(image);
    }
    return image;
}

void writePng(const Image& image, const std::filesystem::path& path) {
    const std::string file = path.string();
    if (image.width < 1 || image.height < 1 ||
        image.pixels.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
        throw core::Error("render::writePng(): " + file + ": the image is " +
                          std::to_string(image.width) + " x " + std::to_string(image.height) +
                          " with " + std::to_string(image.pixels.size()) + " bytes of pixels");
    }
    MessageCapture capture;
    Bitmap bitmap(FreeImage_Allocate(image.width, image.height, 32, FI_RGBA_RED_MASK,
                                     FI_RGBA_GREEN_MASK, FI_RGBA_BLUE_MASK));
    if (bitmap.bitmap == nullptr) {
        throw core::Error("render::writePng(): " + file + ": " + capture.reason("out of memory"));
    }
    auto w = static_cast<unsigned>(image.width);
    auto h = static_cast<unsigned>(image.height);
    for (unsigned y = 0; y < h; ++y) {
        BYTE* dst = FreeImage_GetScanLine(bitmap.bitmap, static_cast<int>(h - 1 - y));
        const std::uint8_t* src = image.pixels.data() + static_cast<std::size_t>(y) * w * 4;
        for (unsigned x = 0; x < w; ++x) {
            dst[x * 4 + FI_RGBA_RED] = src[x * 4 + 0];
            dst[x * 4 + FI_RGBA_GREEN] = src[x * 4 + 1];
            dst[x * 4 + FI_RGBA_BLUE] = src[x * 4 + 2];
            dst[x * 4 + FI_RGBA_ALPHA] = src[x * 4 + 3];
        }
    }
    if (FreeImage_Save(FIF_PNG, bitmap.bitmap, file.c_str(), PNG_DEFAULT) == FALSE) {
        throw core::Error("render::writePng(): " + file + ": " +
                          capture.reason("FreeImage_Save() failed"));
    }
}

} // namespace e2d::render
