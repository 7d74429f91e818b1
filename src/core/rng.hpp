// rng.hpp - the per-handle pseudo-random generator.
//
// xoshiro256** (Blackman & Vigna 2018), seeded through splitmix64 so that any
// 64-bit seed, including 0, gives a well-mixed state. Doubles are made here
// from the top 53 bits, not by a library distribution, so the same seed gives
// the same stream with every compiler and standard library.
#ifndef PDS_RNG_HPP
#define PDS_RNG_HPP

#include <cstdint>

namespace pds {

// splitmix64's finalizer (Steele, Lea and Flood 2014): every bit of x moves
// about half the bits of the result. The generator's seeding, the per-cell
// dart streams and the hash tables use this one.
inline std::uint64_t mix64(std::uint64_t x) {
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class Rng {
public:
    explicit Rng(std::uint64_t seed) {
        for (std::uint64_t& word : s_) word = splitmix64(seed);
    }

    std::uint64_t next_u64() {
        const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const std::uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }

    // Uniform on [0, 1), multiples of 2^-53.
    double next_double() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    static std::uint64_t splitmix64(std::uint64_t& state) { return mix64(state += 0x9E3779B97F4A7C15ull); }

    std::uint64_t s_[4];
};

}  // namespace pds

#endif
