// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// sampler.hpp — the random numbers of one camera path: sample s of pixel p.
//
//   independent  PCG32 (O'Neill 2014), one stream per (seed, p, s) seeded through SplitMix64.
//                The default, and what Mitsuba's `independent` sampler is.
//   sobol        Owen-scrambled Sobol' points, padded: each 1D or 2D dimension of the path
//                (camera jitter, light choice, light point, lobe choice, lobe direction,
//                Russian roulette) takes the Sobol' (0,2)-sequence's first one or two
//                dimensions at a shuffled index, with its own scramble (Burley 2020,
//                "Practical Hash-based Owen Scrambling", JCGT 9(4): the index shuffled and
//                the point scrambled by nested uniform scrambling in the Laine–Karras hash
//                form; as pbrt-v4's PaddedSobolSampler). Each dimension's first 2^m samples
//                of a pixel are then a (0, m, 2)-net, randomised: unbiased, and converging
//                faster than independent samples where the integrand is smooth in those
//                dimensions.
// Both depend only on (seed, p, s) and the path's own history, so the image stays the same
// for any thread count.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

namespace pgt {

enum class Sampler { INDEPENDENT, SOBOL };

inline std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

class Rng {  // PCG32 (O'Neill 2014, pcg32 XSH RR)
public:
    Rng() : state_(0), inc_(1) {}
    Rng(unsigned seed, std::uint64_t pixel, std::uint64_t sample) {
        std::uint64_t h = splitmix64(splitmix64(splitmix64(seed) ^ pixel) ^ sample);
        inc_ = (splitmix64(h) << 1u) | 1u;
        state_ = 0;
        next();
        state_ += h;
        next();
    }
    std::uint32_t next() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }
    float uniform() { return float(next() >> 8) * (1.0f / 16777216.0f); }  // [0, 1)

private:
    std::uint64_t state_, inc_;
};

namespace sobol {

inline std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// The Laine & Karras 2011 hash with Burley 2020's constants: a bijection of 32-bit words in
// which each bit depends only on itself and the bits below it, and on the seed.
inline std::uint32_t laine_karras(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Nested uniform scrambling in base 2 (Owen 1995) of the bits of x, most significant first:
// each bit flips by a hash of the bits above it (Laine–Karras on the reversed bits).
inline std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    return reverse_bits(laine_karras(reverse_bits(x), seed));
}

// The first two dimensions of Sobol's sequence as 32-bit fractions: the van der Corput
// sequence, and the one of the primitive polynomial x + 1 (direction numbers
// v_1 = 1/2, v_k = v_{k-1} ⊕ v_{k-1}/2). Together a (0, 2)-sequence in base 2.
inline std::uint32_t dim0(std::uint32_t i) { return reverse_bits(i); }
// dim1 by bytes of the index: table b holds the XOR of the direction numbers v_{8b+1..8b+8}
// that each byte value selects (built at compile time; read-only).
struct Dim1Tables {
    std::uint32_t t[4][256];
    constexpr Dim1Tables() : t{} {
        std::uint32_t v[32] = {};
        v[0] = 0x80000000u;
        for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
        for (int b = 0; b < 4; ++b)
            for (int x = 0; x < 256; ++x) {
                std::uint32_t r = 0;
                for (int j = 0; j < 8; ++j)
                    if (x & (1 << j)) r ^= v[8 * b + j];
                t[b][x] = r;
            }
    }
};
inline constexpr Dim1Tables kDim1{};
inline std::uint32_t dim1(std::uint32_t i) {
    return kDim1.t[0][i & 255u] ^ kDim1.t[1][(i >> 8) & 255u] ^ kDim1.t[2][(i >> 16) & 255u] ^ kDim1.t[3][i >> 24];
}

inline float to_float(std::uint32_t x) { return float(x >> 8) * (1.0f / 16777216.0f); }  // [0, 1)

}  // namespace sobol

// The numbers of one path: get1/get2 in the order the path consumes them.
class PathSampler {
public:
    PathSampler() = default;
    PathSampler(Sampler kind, unsigned seed, std::uint64_t pixel, std::uint64_t sample) : kind_(kind) {
        if (kind == Sampler::INDEPENDENT) {
            rng_ = Rng(seed, pixel, sample);
        } else {
            pixel_seed_ = splitmix64(splitmix64(seed) ^ pixel);
            rev_index_ = sobol::reverse_bits(std::uint32_t(sample));
        }
    }
    // Sobol': the shuffled index i = owen_scramble(index, s0), with reverse_bits(index) computed
    // once per path; dimension 0 of Sobol' is reverse_bits(i), so its scramble
    // owen_scramble(reverse_bits(i), s1) is reverse_bits(laine_karras(i, s1)).
    __attribute__((always_inline)) float get1() {
        if (kind_ == Sampler::INDEPENDENT) return rng_.uniform();
        const std::uint64_t h = dim_hash();
        const std::uint32_t i = sobol::reverse_bits(sobol::laine_karras(rev_index_, std::uint32_t(h)));
        return sobol::to_float(sobol::reverse_bits(sobol::laine_karras(i, std::uint32_t(h >> 32))));
    }
    __attribute__((always_inline)) glm::vec2 get2() {
        if (kind_ == Sampler::INDEPENDENT) {
            const float a = rng_.uniform();
            return {a, rng_.uniform()};
        }
        const std::uint64_t h = dim_hash();
        const std::uint32_t i = sobol::reverse_bits(sobol::laine_karras(rev_index_, std::uint32_t(h)));
        std::uint32_t s2 = std::uint32_t(h >> 32) ^ 0xa511e9b3u;  // a third seed (Wellons' lowbias32)
        s2 = (s2 ^ (s2 >> 16)) * 0x7feb352du;
        s2 = (s2 ^ (s2 >> 15)) * 0x846ca68bu;
        s2 ^= s2 >> 16;
        return {sobol::to_float(sobol::reverse_bits(sobol::laine_karras(i, std::uint32_t(h >> 32)))),
                sobol::to_float(sobol::owen_scramble(sobol::dim1(i), s2))};
    }

private:
    std::uint64_t dim_hash() { return splitmix64(pixel_seed_ ^ (std::uint64_t(++dim_) * 0xd1b54a32d192ed03ull)); }
    Sampler kind_ = Sampler::INDEPENDENT;
    Rng rng_;
    std::uint64_t pixel_seed_ = 0;
    std::uint32_t rev_index_ = 0, dim_ = 0;  // the sample's index, bits reversed
};

}  // namespace pgt
