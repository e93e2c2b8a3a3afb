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
#include <sstream>
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
        std::error_code ignored;  // not ec: the removal's success would replace the rename's reason
        fs::remove(tmp, ignored);
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

namespace {

// The extent of `text` at `size` px relative to the first line's baseline origin (OIIO's
// text_size); an empty ROI when the font cannot be found.
OIIO::ROI text_extent(const std::string &text, int size, const std::string &font) {
    return OIIO::ImageBufAlgo::text_size(text, size, font);
}

// How far right of its origin text's widest line reaches at `size` px, with a pixel for the
// anti-aliased edge (0 when the font cannot be found).
int text_width(const std::string &text, int size, const std::string &font) {
    OIIO::ROI r = text_extent(text, size, font);
    return r.defined() ? r.xend + 1 : 0;
}

// The largest size from `start` down to 9 px at which every text is at most `width` wide.
int fitting_size(const std::vector<std::string> &texts, int start, int width, const std::string &font) {
    int size = start;
    for (; size > 9; --size) {
        bool fits = true;
        for (const std::string &t : texts) fits = fits && text_width(t, size, font) <= width;
        if (fits) break;
    }
    return size;
}

// `text` with every line that is wider than `width` broken between words.
std::string wrap(const std::string &text, int width, int size, const std::string &font) {
    std::string out, line;
    std::istringstream lines(text);
    while (std::getline(lines, line)) {
        if (text_width(line, size, font) <= width) {  // kept as written (double spaces too)
            out += line + "\n";
            continue;
        }
        std::istringstream words(line);
        std::string w, cur;
        while (words >> w) {
            std::string next = cur.empty() ? w : cur + " " + w;
            if (!cur.empty() && text_width(next, size, font) > width) {
                out += cur + "\n";
                next = w;
            }
            cur = next;
        }
        out += cur + "\n";
    }
    if (!out.empty()) out.pop_back();
    return out;
}

// Draws `text` on background `bg` into sheet's box (x, y, w, h), first baseline `ascent` below
// y, clipped to the box: a label too long for its cell is cut at the cell's edge instead of
// running into the next.
void text_in_box(OIIO::ImageBuf &sheet, int x, int y, int w, int h, int ascent, const std::string &text, int size,
                 const std::string &font, const float *colour, const float *bg) {
    OIIO::ImageBuf box(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(box, {bg, 3});
    OIIO::ImageBufAlgo::render_text(box, 0, ascent, text, size, font, {colour, 3});
    OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, box);
}

}  // namespace

Image contact_sheet(const std::vector<SheetCell> &cells, int columns, const std::string &title) {
    if (cells.empty()) return {};
    const int cw = cells[0].display.width, ch = cells[0].display.height;
    const int rows = (int(cells.size()) + columns - 1) / columns;
    const int pad = 6, W = pad + columns * (cw + pad);
    const std::string fontname = "DejaVuSans";
    // Label and title sizes: as large as cw / 13, smaller where a line would not fit its cell
    // (or the title the sheet), and lines still too wide broken between words; the label rows
    // as tall as the tallest label.
    std::vector<std::string> labels;
    for (const SheetCell &c : cells) labels.push_back(c.label);
    const int font = fitting_size(labels, std::max(10, cw / 13), cw - 6, fontname);
    for (std::string &l : labels) l = wrap(l, cw - 6, font, fontname);
    const int title_font = fitting_size({title}, std::max(10, cw / 13), W - 2 * pad, fontname);
    const std::string title_text = wrap(title, W - 2 * pad, title_font, fontname);
    int ascent = font, descent = font / 3;
    for (const std::string &l : labels) {
        OIIO::ROI r = text_extent(l, font, fontname);
        if (r.defined()) ascent = std::max(ascent, -r.ybegin), descent = std::max(descent, r.yend);
    }
    OIIO::ROI tr = text_extent(title_text, title_font, fontname);
    const int title_ascent = tr.defined() ? std::max(title_font, -tr.ybegin) : title_font;
    const int title_h = title_ascent + (tr.defined() ? std::max(0, tr.yend) : title_font / 3) + 12;
    const int label_h = ascent + descent + 6;
    const int H = title_h + rows * (ch + label_h + pad);
    OIIO::ImageBuf sheet(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::FLOAT));
    const float bg[3] = {0.08f, 0.08f, 0.08f}, white[3] = {1.0f, 1.0f, 1.0f}, light[3] = {0.9f, 0.9f, 0.9f};
    OIIO::ImageBufAlgo::fill(sheet, {bg, 3});
    text_in_box(sheet, pad, 4, W - 2 * pad, title_h - 4, title_ascent, title_text, title_font, fontname, white, bg);
    for (size_t i = 0; i < cells.size(); ++i) {
        int col = int(i) % columns, row = int(i) / columns;
        int x = pad + col * (cw + pad), y = title_h + row * (ch + label_h + pad);
        const Image &d = cells[i].display;
        OIIO::ImageBuf cell(OIIO::ImageSpec(d.width, d.height, 3, OIIO::TypeDesc::FLOAT),
                            const_cast<float *>(d.rgb.data()));
        OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, cell);
        text_in_box(sheet, x + 2, y + ch + 3, cw - 2, label_h - 3, ascent, labels[i], font, fontname, light, bg);
    }
    Image out;
    out.width = W, out.height = H;
    out.rgb.resize(size_t(W) * size_t(H) * 3);
    sheet.get_pixels(OIIO::ROI(0, W, 0, H, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, out.rgb.data());
    return out;
}

}  // namespace pgt
