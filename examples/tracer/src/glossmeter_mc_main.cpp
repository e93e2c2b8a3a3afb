// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-glossmeter-mc — the Monte Carlo virtual glossmeter (glossmeter_mc.hpp) against
// pgloss/glossmeter.h's quadrature, side by side: value, standard error, z-score, and the time
// each took. Usage: pgloss-glossmeter-mc [--samples N] [--seed S]
#include "glossmeter_mc.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char **argv) {
    std::uint64_t n = 1u << 20;
    unsigned seed = 1;
    for (int k = 1; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--samples") && k + 1 < argc) n = std::strtoull(argv[++k], nullptr, 10);
        else if (!std::strcmp(argv[k], "--seed") && k + 1 < argc) seed = unsigned(std::strtoul(argv[++k], nullptr, 10));
        else {
            std::fprintf(stderr, "usage: pgloss-glossmeter-mc [--samples N] [--seed S]\n");
            return 2;
        }
    }
    static const char *const kind_name[] = {"G20", "G60", "G85", "haze20", "", "DOI30", ""};
    std::printf("| paint | reading | Monte Carlo | std. error | quadrature | its error | z | MC s | quadrature ms |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    double chi2 = 0;
    int dof = 0;
    unsigned stream = 0;  // one PCG32 stream per case, so that the z-scores are independent
    for (const auto &c : pgt::glossmeter_mc_cases())
        for (pgloss_glossmeter_kind kind : c.kinds) {
            const pgt::GlossmeterMc mc = pgt::glossmeter_mc(kind, c.paint, c.azimuth_deg, n, 1000 * seed + stream++);
            pgloss_gloss_reading q;
            const auto t0 = std::chrono::steady_clock::now();
            pgloss_glossmeter_read_physical(kind, &c.paint, c.azimuth_deg, 1e-6, &q);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            const double z = (mc.value - q.value) / std::sqrt(mc.std_error * mc.std_error + q.error * q.error);
            chi2 += z * z;
            ++dof;
            std::printf("| %s | %s | %.4f | %.4f | %.4f | %.1e | %+.2f | %.2f | %.1f |\n", c.name.c_str(), kind_name[kind],
                        mc.value, mc.std_error, q.value, q.error, z, mc.seconds, ms);
        }
    std::printf("\nchi-square %.1f on %d readings (%llu samples each, seed %u)\n", chi2, dof, (unsigned long long)n, seed);
    return 0;
}
