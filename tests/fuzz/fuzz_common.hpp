// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// fuzz_common.hpp — turning libFuzzer's bytes into numbers, and failing loudly. Each value is
// drawn either from a distribution over the regular range or as raw bits (NaN, ±Inf,
// denormals, ±0, huge values), so that one corpus covers both the contracts on ordinary input
// and the error paths.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace fz {

[[noreturn]] inline void fail(const char *what, const char *file, int line) {
    std::fprintf(stderr, "contract violated at %s:%d: %s\n", file, line, what);
    std::abort();
}
#define FZ_CHECK(cond)                                  \
    do {                                                \
        if (!(cond)) fz::fail(#cond, __FILE__, __LINE__); \
    } while (0)

class Bytes {
public:
    Bytes(const std::uint8_t *p, size_t n) : p_(p), n_(n) {}
    template <class T> T raw() {
        T v{};
        size_t k = n_ < sizeof(T) ? n_ : sizeof(T);
        std::memcpy(&v, p_, k);
        p_ += k, n_ -= k;
        return v;
    }
    std::uint8_t byte() { return raw<std::uint8_t>(); }
    double unit() { return raw<std::uint16_t>() / 65535.0; }  // [0, 1]
    bool empty() const { return n_ == 0; }

    // A double: mostly in [lo, hi] (log-uniform when lo > 0 and hi/lo is large), sometimes a
    // special value, sometimes raw bits.
    double real(double lo, double hi) {
        switch (byte() % 8) {
        case 0: return raw<double>();
        case 1: {
            static const double special[] = {0.0, -0.0, 1.0, -1.0, 1e-300, 5e-324, 2.2250738585072014e-308,
                                             1.1754943508222875e-38, 3.4028234663852886e38, 1e308,
                                             std::numeric_limits<double>::infinity(),
                                             -std::numeric_limits<double>::infinity(),
                                             std::numeric_limits<double>::quiet_NaN(), 1e-12, 1 - 1e-12, 1e-4};
            return special[byte() % (sizeof special / sizeof special[0])];
        }
        default: {
            double t = unit();
            if (lo > 0 && hi / lo > 100) return lo * std::pow(hi / lo, t);
            return lo + (hi - lo) * t;
        }
        }
    }
    float realf(float lo, float hi) {
        if (byte() % 8 == 0) return raw<float>();
        return float(real(lo, hi));
    }

private:
    const std::uint8_t *p_;
    size_t n_;
};

inline bool finite3(float a, float b, float c) { return std::isfinite(a) && std::isfinite(b) && std::isfinite(c); }

}  // namespace fz
