// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The Monte Carlo virtual glossmeter (glossmeter_mc.hpp).
#include "glossmeter_mc.hpp"

#include "sampler.hpp"
#include "sphrect.hpp"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace pgt {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Rect { double s0, s1, t0, t1; };

Rect rect_of(const pgloss_glossmeter_window &w) {
    return {std::tan((w.center_deg - 0.5 * w.width_deg) * kDeg), std::tan((w.center_deg + 0.5 * w.width_deg) * kDeg),
            -std::tan(0.5 * w.height_deg * kDeg), std::tan(0.5 * w.height_deg * kDeg)};
}

// Embree's device and scene, released in reverse order.
struct Rtc {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    Rtc() {
        device = rtcNewDevice("threads=1");
        if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
        scene = rtcNewScene(device);
    }
    ~Rtc() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
    Rtc(const Rtc &) = delete;
    Rtc &operator=(const Rtc &) = delete;

    unsigned quad(const glm::dvec3 c[4]) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
        auto *v = static_cast<float *>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
        for (int k = 0; k < 4; ++k)
            v[3 * k] = float(c[k].x), v[3 * k + 1] = float(c[k].y), v[3 * k + 2] = float(c[k].z);
        auto *ix = static_cast<unsigned *>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), 1));
        ix[0] = 0, ix[1] = 1, ix[2] = 2, ix[3] = 3;
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        return id;
    }

    // The geometry hit first along o + t d (t > tnear), and the hit point; RTC_INVALID_GEOMETRY_ID if none.
    unsigned trace(glm::dvec3 o, glm::dvec3 d, float tnear, glm::dvec3 *p) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh{};
        rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
        rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
        rh.ray.tnear = tnear;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        if (p) *p = o + double(rh.ray.tfar) * d;
        return rh.hit.geomID;
    }
};

double uniform53(Rng &r) {  // [0, 1) with 53 bits
    const std::uint64_t a = r.next() >> 5, b = r.next() >> 6;
    return double(a * 67108864ull + b) * (1.0 / 9007199254740992.0);
}

}  // namespace

GlossmeterMc glossmeter_mc(pgloss_glossmeter_kind kind, const pgloss_physical &paint, double azimuth_deg,
                           std::uint64_t n, unsigned seed) {
    if (kind != PGLOSS_GLOSS_20 && kind != PGLOSS_GLOSS_60 && kind != PGLOSS_GLOSS_85 && kind != PGLOSS_HAZE_20 &&
        kind != PGLOSS_DOI_30)
        throw std::invalid_argument("glossmeter_mc: no Monte Carlo instrument for this kind");
    pgloss_material m;
    if (pgloss_material_init(&m, &paint) != PGLOSS_OK || n == 0)
        throw std::invalid_argument("glossmeter_mc: invalid paint or sample count");
    pgloss_glossmeter_geometry g;
    pgloss_glossmeter_geometry_of(kind, &g);
    const auto t_start = std::chrono::steady_clock::now();

    // The frames of pgloss/glossmeter.h: source and receptor axes, their in-plane directions away
    // from the normal, and v across the plane of measurement.
    const double st = std::sin(g.theta_deg * kDeg), ct = std::cos(g.theta_deg * kDeg);
    const glm::dvec3 ai(-st, 0, ct), ui(-ct, 0, -st), ao(st, 0, ct), uo(ct, 0, -st), v(0, 1, 0);

    Rtc rtc;
    // off-centre, so that the sample point (the origin) is not on the quad's diagonal, where a
    // ray may slip between Embree's two triangles
    const glm::dvec3 sample[4] = {{-10, -9, 0}, {11, -9, 0}, {11, 12, 0}, {-10, 12, 0}};
    const unsigned sample_id = rtc.quad(sample);
    std::vector<pgloss_glossmeter_window> wins = {g.specular};
    for (int k = 0; k < g.n_off; ++k) wins.push_back(g.off[k]);
    std::vector<unsigned> ids;
    for (const auto &w : wins) {
        const Rect r = rect_of(w);
        const glm::dvec3 c[4] = {ao + r.s0 * uo + r.t0 * v, ao + r.s1 * uo + r.t0 * v, ao + r.s1 * uo + r.t1 * v,
                                 ao + r.s0 * uo + r.t1 * v};
        ids.push_back(rtc.quad(c));
    }
    rtcCommitScene(rtc.scene);

    // The source window as a spherical rectangle seen from the sample point.
    const Rect sr = rect_of(g.source);
    const RectFrame src = rect_frame(glm::vec3(ai + sr.s0 * ui + sr.t0 * v), glm::vec3((sr.s1 - sr.s0) * ui),
                                     glm::vec3((sr.t1 - sr.t0) * v), glm::vec3(-ai));
    const SphRect sph = sphrect_setup(src, glm::vec3(0.0f));
    if (sph.state != SphRect::OK) throw std::runtime_error("glossmeter_mc: source window is degenerate");
    const glm::dvec3 corner = ai + sr.s0 * ui + sr.t0 * v;
    const Rect spec = rect_of(g.specular);
    const double ca = std::cos(azimuth_deg * kDeg), sa = std::sin(azimuth_deg * kDeg);

    // Per sample: x[k] the flux into window k, y the standard's flux (both × the source's solid
    // angle); the sums needed for the ratio estimators' delta method.
    const size_t nw = wins.size();
    std::vector<double> sx(nw, 0.0);
    double sy = 0, syy = 0, sxx0 = 0, sxy0 = 0, sm = 0, smm = 0, smx0 = 0, smy = 0;
    Rng rng(seed, std::uint64_t(kind), 0);
    for (std::uint64_t i = 0; i < n; ++i) {
        const glm::dvec2 off = sphrect_sample(src, sph, uniform53(rng), uniform53(rng));
        const glm::dvec3 to_src = glm::normalize(corner + off.x * src.ex + off.y * src.ey);
        // the standard: the mirror ray of index 1.567 lands in the specular window if (s, −t) does
        const double s = glm::dot(to_src, ui) / glm::dot(to_src, ai), t = glm::dot(to_src, v) / glm::dot(to_src, ai);
        double y = 0;
        if (s >= spec.s0 && s <= spec.s1 && -t >= spec.t0 && -t <= spec.t1)
            pgloss_fresnel_dielectric(g.standard_index, to_src.z, &y);
        y *= sph.S;
        // the beam meets the sample
        glm::dvec3 p;
        if (rtc.trace(2.0 * to_src, -to_src, 0.0f, &p) != sample_id)
            throw std::runtime_error("glossmeter_mc: the beam missed the sample");
        // reflection by the paint, in its rotated frame
        const pgloss_vec3 wo = {float(ca * to_src.x + sa * to_src.y), float(-sa * to_src.x + ca * to_src.y),
                                float(to_src.z)};
        const float u[3] = {rng.uniform(), rng.uniform(), rng.uniform()};
        pgloss_sample_record rec;
        pgloss_sample(&m, wo, u, PGLOSS_LOBE_ALL, &rec);
        double x[3] = {0, 0, 0};
        if (rec.pdf > 0) {
            const glm::dvec3 r(ca * rec.wi.x - sa * rec.wi.y, sa * rec.wi.x + ca * rec.wi.y, rec.wi.z);
            const unsigned hit = rtc.trace(p, glm::normalize(r), 1e-4f, nullptr);
            for (size_t k = 0; k < nw; ++k)
                if (hit == ids[k])
                    x[k] = sph.S * (PGLOSS_LUMA_R * rec.weight.r + PGLOSS_LUMA_G * rec.weight.g +
                                    PGLOSS_LUMA_B * rec.weight.b);
        }
        for (size_t k = 0; k < nw; ++k) sx[k] += x[k];
        const double xm = nw == 3 ? (kind == PGLOSS_DOI_30 ? 0.5 : 1.0) * (x[1] + x[2]) : x[0];
        sy += y, syy += y * y;
        sxx0 += x[0] * x[0], sxy0 += x[0] * y;
        sm += xm, smm += xm * xm, smx0 += xm * x[0], smy += xm * y;
    }
    const double N = double(n);
    GlossmeterMc out;
    out.samples = n;
    // a ratio a/b of means and its delta-method standard error from the sums
    auto ratio = [N](double sa_, double sb, double saa, double sbb, double sab, double *se) {
        const double r = sa_ / sb;
        const double var_z = (saa - 2 * r * sab + r * r * sbb) / N - std::pow((sa_ - r * sb) / N, 2);
        *se = std::sqrt(std::max(0.0, var_z) / (N - 1)) / (sb / N);
        return r;
    };
    double se;
    if (kind == PGLOSS_DOI_30) {
        const double r = ratio(sm, sx[0], smm, sxx0, smx0, &se);
        out.value = 100.0 * (1.0 - r);
        out.std_error = 100.0 * se;
    } else if (kind == PGLOSS_HAZE_20) {
        out.value = 100.0 * ratio(sm, sy, smm, syy, smy, &se);
        out.std_error = 100.0 * se;
    } else {
        out.value = 100.0 * ratio(sx[0], sy, sxx0, syy, sxy0, &se);
        out.std_error = 100.0 * se;
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return out;
}

std::vector<GlossmeterMcCase> glossmeter_mc_cases() {
    std::vector<GlossmeterMcCase> cases;
    const std::vector<pgloss_glossmeter_kind> gloss = {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60, PGLOSS_GLOSS_85};
    for (size_t k = 0; pgloss_finish_at(k); ++k) {
        const pgloss_finish *f = pgloss_finish_at(k);
        pgloss_perceptual q;
        pgloss_physical p;
        double c[2], d[2];
        if (pgloss_finish_paint(f, 50.0, 0.0, 0.0, PGLOSS_NORM_WARD, &q, &p, c, d, nullptr) < 0)
            throw std::runtime_error(std::string("glossmeter_mc_cases: no paint for ") + f->name);
        cases.push_back({f->name, p, 0.0, gloss});
    }
    cases.push_back({"black sharp", {{0.03, 0.03, 0.03}, 0.05, 0.01, 0.01, PGLOSS_NORM_WARD}, 0.0,
                     {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60, PGLOSS_GLOSS_85, PGLOSS_HAZE_20, PGLOSS_DOI_30}});
    cases.push_back({"anisotropic", {{0.4, 0.2, 0.1}, 0.08, 0.03, 0.09, PGLOSS_NORM_WARD_DUR}, 30.0,
                     {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60, PGLOSS_GLOSS_85, PGLOSS_HAZE_20}});
    return cases;
}

}  // namespace pgt
