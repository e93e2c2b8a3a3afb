// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// display.frag.glsl — the running mean of the accumulated sums, shown as the tracer shows its
// PNG (examples/tracer/src/image.cpp display_image): exposure, the rational sigmoid
// s(x) = x / (1 + (x/limit)^n)^(1/n) on luminance (colour kept), then the sRGB transfer
// function of IEC 61966-2-1 (the tracer's OCIO config), clamped to [0, 1].
//#version is prepended by render.js.
precision highp float;
uniform sampler2D u_sum;
uniform float u_count;       // samples per pixel accumulated
uniform float u_exposure, u_limit, u_sharpness;
out vec4 o_color;

float srgb_oetf(float v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

void main() {
    vec3 c = texelFetch(u_sum, ivec2(gl_FragCoord.xy), 0).rgb / max(u_count, 1.0);
    float Y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    float x = u_exposure * Y;
    float k = x > 0.0 ? u_exposure / pow(1.0 + pow(x / u_limit, u_sharpness), 1.0 / u_sharpness) : 0.0;
    c = max(c * k, 0.0);
    o_color = vec4(clamp(vec3(srgb_oetf(c.r), srgb_oetf(c.g), srgb_oetf(c.b)), 0.0, 1.0), 1.0);
}
