// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// image.cpp — see image.hpp.
#include "image.hpp"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace OCIO = OCIO_NAMESPACE;

namespace pgt {

float tonemap_sigmoid(float x, const ToneMap &tm) {
    if (!(x > 0)) return 0.0f;
    // In double, so that the rounded result stays monotonic up to the asymptote.
    const double r = double(x) / tm.limit, n = tm.sharpness;
    return float(double(x) / std::pow(1.0 + std::pow(r, n), 1.0 / n));
}

namespace {

// Writes `path` through a temporary file in the same folder (same extension, so that OIIO
// picks the same format) renamed into place: an interrupted or failed write never leaves a
// truncated image under the final name, and an older image there stays whole until replaced.
void write_image_atomically(const std::string &path, const OIIO::ImageSpec &spec, OIIO::TypeDesc type,
                            const void *pixels) {
    namespace fs = std::filesystem;
    fs::path final_path(path);
    fs::path tmp = final_path.parent_path() /
                   ("." + final_path.stem().string() + ".tmp" + std::to_string(getpid()) + final_path.extension().string());
    std::string err;
    {
        auto out = OIIO::ImageOutput::create(tmp.string());
        if (!out) err = OIIO::geterror();
        else if (!out->open(tmp.string(), spec) || !out->write_image(type, pixels) || !out->close())
            err = out->geterror();
    }
    std::error_code ec;
    if (err.empty()) fs::rename(tmp, final_path, ec);
    if (!err.empty() || ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write " + path + ": " + (err.empty() ? ec.message() : err));
    }
}

}  // namespace

void write_exr(const Image &img, const std::string &path) {
    OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B"};
    spec.attribute("compression", "zip");
    spec.attribute("oiio:ColorSpace", "Linear");
    write_image_atomically(path, spec, OIIO::TypeDesc::FLOAT, img.rgb.data());
}

Image read_image(const std::string &path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read " + path + ": " + OIIO::geterror());
    const OIIO::ImageSpec &spec = in->spec();
    std::vector<float> all(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read " + path + ": " + in->geterror());
    Image img;
    img.width = spec.width, img.height = spec.height;
    img.rgb.resize(size_t(spec.width) * size_t(spec.height) * 3);
    for (size_t i = 0; i < size_t(spec.width) * size_t(spec.height); ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * i + size_t(c)] = all[i * size_t(spec.nchannels) + size_t(std::min(c, spec.nchannels - 1))];
    return img;
}

std::string ocio_config_path() {
    if (const char *e = std::getenv("PGLOSS_OCIO_CONFIG")) return e;
    return std::string(PGLOSS_TRACER_DIR) + "/ocio/config.ocio";
}

Image display_image(const Image &lin, const ToneMap &tm) {
    Image out = lin;
    for (size_t i = 0; i < out.rgb.size(); i += 3) {
        float *c = &out.rgb[i];
        float Y = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
        float x = tm.exposure * Y;
        float k = x > 0 ? tm.exposure * tonemap_sigmoid(x, tm) / x : 0.0f;
        for (int j = 0; j < 3; ++j) c[j] = std::max(0.0f, c[j] * k);
    }
    static OCIO::ConstCPUProcessorRcPtr cpu = [] {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(ocio_config_path().c_str());
        config->validate();
        return config->getProcessor("lin_rec709", "srgb_display")->getDefaultCPUProcessor();
    }();
    OCIO::PackedImageDesc desc(out.rgb.data(), out.width, out.height, 3);
    cpu->apply(desc);
    for (float &v : out.rgb) v = std::clamp(v, 0.0f, 1.0f);
    return out;
}

void write_png(const Image &disp, const std::string &path) {
    std::vector<unsigned char> px(disp.rgb.size());
    for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<unsigned char>(std::lround(disp.rgb[i] * 255.0f));
    OIIO::ImageSpec spec(disp.width, disp.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    write_image_atomically(path, spec, OIIO::TypeDesc::UINT8, px.data());
}

Image contact_sheet(const std::vector<SheetCell> &cells, int columns, const std::string &title) {
    if (cells.empty()) return {};
    const int cw = cells[0].display.width, ch = cells[0].display.height;
    const int pad = 6, font = std::max(10, cw / 13), label_h = 2 * font + 6, title_h = font + 16;
    const int rows = (int(cells.size()) + columns - 1) / columns;
    const int W = pad + columns * (cw + pad), H = title_h + rows * (ch + label_h + pad);
    OIIO::ImageBuf sheet(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(sheet, {0.08f, 0.08f, 0.08f});
    const std::string fontname = "DejaVuSans";
    OIIO::ImageBufAlgo::render_text(sheet, pad, title_h - 8, title, font, fontname, {1.0f, 1.0f, 1.0f});
    for (size_t i = 0; i < cells.size(); ++i) {
        int col = int(i) % columns, row = int(i) / columns;
        int x = pad + col * (cw + pad), y = title_h + row * (ch + label_h + pad);
        const Image &d = cells[i].display;
        OIIO::ImageBuf cell(OIIO::ImageSpec(d.width, d.height, 3, OIIO::TypeDesc::FLOAT),
                            const_cast<float *>(d.rgb.data()));
        OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, cell);
        OIIO::ImageBufAlgo::render_text(sheet, x + 2, y + ch + font + 2, cells[i].label, font, fontname,
                                        {0.9f, 0.9f, 0.9f});
    }
    Image out;
    out.width = W, out.height = H;
    out.rgb.resize(size_t(W) * size_t(H) * 3);
    sheet.get_pixels(OIIO::ROI(0, W, 0, H, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, out.rgb.data());
    return out;
}

}  // namespace pgt
