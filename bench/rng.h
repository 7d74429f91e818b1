/*
 * rng.h - the baselines' and probes' random numbers: xoshiro256** seeded by
 * splitmix64. Header-only so the hot loops inline it. Not the library's
 * generator (that one is internal); any good 64-bit generator will do here.
 */
#ifndef BENCH_RNG_H
#define BENCH_RNG_H

#include <stdint.h>

struct bench_rng {
    uint64_t s[4];
};

static inline uint64_t bench_rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

/* splitmix64 spreads a small seed (1, 2, 3...) over the whole state. */
static inline void bench_rng_seed(struct bench_rng *g, uint64_t seed) {
    int i;
    for (i = 0; i < 4; ++i) {
        uint64_t z = (seed += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        g->s[i] = z ^ (z >> 31);
    }
}

static inline uint64_t bench_rng_next(struct bench_rng *g) {
    uint64_t *s = g->s;
    uint64_t result = bench_rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = bench_rotl(s[3], 45);
    return result;
}

/* Uniform in [0, 1): the top 53 bits. */
static inline double bench_rng_uniform(struct bench_rng *g) {
    return (double)(bench_rng_next(g) >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform in [0, n) for n < 2^32, by the multiply-shift map (bias < 2^-32). */
static inline uint32_t bench_rng_below(struct bench_rng *g, uint32_t n) {
    return (uint32_t)(((bench_rng_next(g) >> 32) * (uint64_t)n) >> 32);
}

#endif /* BENCH_RNG_H */
