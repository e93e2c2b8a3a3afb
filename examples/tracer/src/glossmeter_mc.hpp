// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// glossmeter_mc.hpp — a Monte Carlo virtual glossmeter: the check of pgloss/glossmeter.h's
// quadrature by simulation, with the tracer's own parts (Embree, the spherical-rectangle sampler,
// the PCG32 streams).
//
// The instrument (pgloss/glossmeter.h, "Windows"): a collimated beam at the geometry's angle whose
// directions fill the source window uniformly in solid angle (the source field stop, sampled as a
// spherical rectangle, sphrect.hpp) meets a flat sample (an Embree quad through the origin,
// rotated by the azimuth about its normal); pgloss_sample reflects each ray; a reflected ray counts
// where it crosses a receptor window — an Embree quad perpendicular to the receptor axis at unit
// distance, the field stop of an ideal receptor lens of unit focal length. The primary standard
// (glass of index 1.567) is read by the same source samples with its exact Fresnel reflectance.
// A reading is a ratio of means of per-sample values; its standard error is the delta method's.
#pragma once
extern "C" {
#include "pgloss/pgloss.h"
}

#include <cstdint>
#include <string>
#include <vector>

namespace pgt {

struct GlossmeterMc {
    double value = 0;          // the reading (pgloss_glossmeter_read's units)
    double std_error = 0;      // its standard error
    std::uint64_t samples = 0;
    double seconds = 0;
};

// The reading `kind` (GLOSS_20, GLOSS_60, GLOSS_85, HAZE_20 or DOI_30) of a paint by n samples of
// PCG32 stream `seed`. Throws std::invalid_argument for another kind or an invalid paint.
GlossmeterMc glossmeter_mc(pgloss_glossmeter_kind kind, const pgloss_physical &paint, double azimuth_deg,
                           std::uint64_t n, unsigned seed);

// The paints the Monte Carlo check reads, across the finish range: the representative paint of each
// MPI gloss level G1–G7 at L* = 50 (pgloss_finish_paint), a sharp black paint and an anisotropic,
// rotated Dür-normalised one; with the kinds to read for each.
struct GlossmeterMcCase {
    std::string name;
    pgloss_physical paint;
    double azimuth_deg;
    std::vector<pgloss_glossmeter_kind> kinds;
};
std::vector<GlossmeterMcCase> glossmeter_mc_cases();

}  // namespace pgt
