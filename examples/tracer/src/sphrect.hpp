// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// sphrect.hpp — uniform sampling of the solid angle a rectangular light subtends at a point:
// the area-preserving parametrisation of spherical rectangles of Ureña, Fajardo & King 2013
// ("An Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013, §3–4).
//
// Area sampling of a light (pdf dist² / (A cos θ_l) in solid angle) is noisy where cos θ_l / dist²
// varies over the light: near it and at grazing angles. Sampling the solid angle uniformly
// (pdf 1/S) takes both factors out of the estimator; only the receiver's cosine, the BRDF and
// the visibility are left to vary.
//
// Numerics. The set-up is in double: S = Σ γ_i − 2π loses its leading digits for a small or
// grazing rectangle. Each interior angle γ_i is taken as atan2(sin, cos) of closed forms (well
// conditioned, unlike the paper's acos of a dot product), and γ0 + γ1, γ2 + γ3 as the arguments
// of complex products (two atan2 instead of four). Where the spherical rectangle degenerates —
// the point (nearly) in the light's plane, S below kMinSolidAngle, a parallelogram that is not a
// rectangle — the caller falls back to area sampling; the choice depends on the point alone,
// so the pdf that MIS evaluates for a BRDF-sampled ray reaching the light is the same.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace pgt {

// A rectangle as the sampler needs it: corner, orthonormal edge directions ex, ey, the normal
// ez of the emitting side (any handedness: the parametrisation is in the local frame, and an
// isometry keeps solid angles), edge lengths.
struct RectFrame {
    glm::dvec3 corner{0}, ex{0}, ey{0}, ez{0};
    double lx = 0, ly = 0;
    bool valid = false;  // a rectangle (edges orthogonal to 1e-6) with both edges > 0
};

inline RectFrame rect_frame(glm::vec3 corner, glm::vec3 edge1, glm::vec3 edge2, glm::vec3 normal) {
    RectFrame r;
    const glm::dvec3 e1(edge1), e2(edge2);
    r.lx = glm::length(e1), r.ly = glm::length(e2);
    if (!(r.lx > 0 && r.ly > 0) || !std::isfinite(r.lx * r.ly)) return r;
    r.corner = glm::dvec3(corner);
    r.ex = e1 / r.lx, r.ey = e2 / r.ly, r.ez = glm::normalize(glm::dvec3(normal));
    r.valid = std::abs(glm::dot(r.ex, r.ey)) <= 1e-6 && std::abs(std::abs(glm::dot(glm::cross(r.ex, r.ey), r.ez)) - 1) <= 1e-6;
    // Edges given in float are orthogonal only to float's precision: make the frame exactly
    // orthonormal, so that the parametrisation's rectangle is the one its samples lie on (it
    // differs from the light by < 1e-6 of its size).
    r.ey = glm::normalize(r.ey - glm::dot(r.ey, r.ex) * r.ex);
    r.ez = glm::dot(glm::cross(r.ex, r.ey), r.ez) > 0 ? glm::cross(r.ex, r.ey) : -glm::cross(r.ex, r.ey);
    return r;
}

// The spherical rectangle of a RectFrame seen from o (Ureña et al. 2013, §3, local frame with
// the rectangle in the plane z = z0 < 0 and o at the origin).
struct SphRect {
    enum State { BEHIND, DEGENERATE, OK } state = DEGENERATE;
    double S = 0;                  // solid angle (sr)
    double k = 0, b0 = 0, b1 = 0;  // the paper's k = 2π − γ2 − γ3, b0 = n0.z, b1 = n2.z
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0;
};

// Below this solid angle (sr) the rectangle is sampled by area: there cos θ_l / dist² hardly
// varies over it, and S's relative rounding error (~1e-16 / S) would start to show.
constexpr double kMinSolidAngle = 1e-6;

// BEHIND: o is on the back of the one-sided light or in its plane (it receives nothing).
// DEGENERATE: sample by area instead. OK: sample with sphrect_sample, pdf 1/S.
inline SphRect sphrect_setup(const RectFrame &r, glm::vec3 o) {
    SphRect q;
    if (!r.valid) return q;
    const glm::dvec3 d = r.corner - glm::dvec3(o);
    q.z0 = glm::dot(d, r.ez);
    if (!(q.z0 < 0)) {
        q.state = SphRect::BEHIND;
        return q;
    }
    q.x0 = glm::dot(d, r.ex), q.y0 = glm::dot(d, r.ey);
    q.x1 = q.x0 + r.lx, q.y1 = q.y0 + r.ly;
    const double z0 = q.z0, z2 = z0 * z0, a = -z0;
    const double x0 = q.x0, x1 = q.x1, y0 = q.y0, y1 = q.y1;
    // The interior angle at each vertex, as (cos, sin) up to a common positive factor:
    // cos γ = −n_i·n_{i+1}, sin γ = |n_i × n_{i+1}| = |z0| |v| / (…) (v the vertex).
    const double c0 = y0 * x1, s0 = a * std::sqrt(x1 * x1 + y0 * y0 + z2);   // γ0 at v10
    const double c1 = -x1 * y1, s1 = a * std::sqrt(x1 * x1 + y1 * y1 + z2);  // γ1 at v11
    const double c2 = x0 * y1, s2 = a * std::sqrt(x0 * x0 + y1 * y1 + z2);   // γ2 at v01
    const double c3 = -x0 * y0, s3 = a * std::sqrt(x0 * x0 + y0 * y0 + z2);  // γ3 at v00
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    auto arg = [](double re, double im) {  // in [0, 2π): γ_i + γ_j lies in (0, 2π)
        const double t = std::atan2(im, re);
        return t < 0 ? t + kTwoPi : t;
    };
    const double g01 = arg(c0 * c1 - s0 * s1, c0 * s1 + s0 * c1);
    const double g23 = arg(c2 * c3 - s2 * s3, c2 * s3 + s2 * c3);
    q.k = kTwoPi - g23;
    q.S = g01 - q.k;
    q.b0 = -y0 / std::sqrt(z2 + y0 * y0);
    q.b1 = y1 / std::sqrt(z2 + y1 * y1);
    q.state = q.S >= kMinSolidAngle && std::isfinite(q.S) && std::isfinite(q.b0) && std::isfinite(q.b1)
                  ? SphRect::OK : SphRect::DEGENERATE;
    return q;
}

// The point of the rectangle in direction ω(u, v), ω uniform in the solid angle for (u, v)
// uniform in [0, 1)² (Ureña et al. 2013, §4, eqs. of the inverse of u(x) and v(y)), as offsets
// (along ex, ey) from the corner: the sample lies on the light whatever the rounding.
inline glm::dvec2 sphrect_sample(const RectFrame &r, const SphRect &q, double u, double v) {
    const double au = u * q.S + q.k;
    const double sa = std::sin(au), ca = std::cos(au);
    const double fu = (ca * q.b0 - q.b1) / sa;  // ±inf at sin au = 0: cu = ±0 below, the limit
    double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + q.b0 * q.b0);
    cu = std::clamp(std::isfinite(cu) ? cu : 0.0, -1.0, 1.0);
    const double xu = std::clamp(-(cu * q.z0) / std::sqrt(std::max(1e-300, 1 - cu * cu)), q.x0, q.x1);
    const double dd = std::sqrt(xu * xu + q.z0 * q.z0);
    const double h0 = q.y0 / std::sqrt(dd * dd + q.y0 * q.y0);
    const double h1 = q.y1 / std::sqrt(dd * dd + q.y1 * q.y1);
    const double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1 - 1e-14 ? hv * dd / std::sqrt(1 - hv2) : (hv > 0 ? q.y1 : q.y0);
    return {std::clamp(xu - q.x0, 0.0, r.lx), std::clamp(std::clamp(yv, q.y0, q.y1) - q.y0, 0.0, r.ly)};
}

}  // namespace pgt
