// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// image.hpp — linear EXR output (OIIO), the display pipeline (tone mapping + OCIO sRGB),
// labelled contact sheets.
//
// Display pipeline, per pixel of the linear Rec. 709 render:
//   1. exposure:   x = k · Y, Y = Rec. 709 luminance, k = ToneMap::exposure;
//   2. tone map:   the paper (§3.2.3.1) used "Tumblin's [Tumb99] Rational Sigmoid function",
//                  from Tumblin, Hodgins & Guenter, "Two methods for display of high contrast
//                  images", ACM TOG 18(1):56–94, 1999, whose sigmoid "has no effect when applied
//                  to small signals but compresses large signals to fit within an asymptotic
//                  limit" (their abstract). We implement the rational sigmoid with exactly those
//                  two properties (slope 1 at 0, asymptote D):
//                      s(x) = x / (1 + (x / D)^n)^(1/n)
//                  D = ToneMap::limit (display white), n = ToneMap::sharpness (n = 1 is the plain
//                  rational x/(1 + x/D)); see the README's tracer section for the caveat that the
//                  constants of THG99's own equation could not be checked here. (THG99's other
//                  operator, the revised Tumblin-Rushmeier mapping of their foveal method, is a
//                  power law, not this sigmoid.)
//                  Colour is kept: RGB is scaled by s(x)/x (the highlight goes towards white only
//                  through the final clip).
//   3. display:    linear Rec. 709 → sRGB (IEC 61966-2-1 transfer) through OCIO, with the config
//                  shipped in examples/tracer/ocio/config.ocio; then clip to [0, 1], 8 bits.
#pragma once
#include "render.hpp"

#include <string>
#include <vector>

namespace pgt {

float tonemap_sigmoid(float x, const ToneMap &tm);

void write_exr(const Image &img, const std::string &path);
Image read_image(const std::string &path);  // any format OIIO reads, as linear float RGB

// Tone mapped + OCIO display-encoded image, floats in [0, 1] (sRGB-encoded).
Image display_image(const Image &linear, const ToneMap &tm);
void write_png(const Image &display, const std::string &path);

// Path of the OCIO config (env PGLOSS_OCIO_CONFIG overrides the shipped one).
std::string ocio_config_path();

struct SheetCell {
    Image display;      // already display-encoded
    std::string label;  // text under the image (may contain '\n')
};
// Grid of cells, `columns` wide, with a title line on top; text through OIIO (DejaVu Sans).
Image contact_sheet(const std::vector<SheetCell> &cells, int columns, const std::string &title);

}  // namespace pgt
