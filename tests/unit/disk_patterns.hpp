// disk_patterns.hpp - patterns of disks with a variable radius for the unit
// suites: brute-force random sequential adsorption under the library's rule
// (a dart is kept when it lies outside every earlier disk, |p - p_i| >= r_i)
// and a weighted mesh built from them.
#ifndef PDS_TEST_DISK_PATTERNS_HPP
#define PDS_TEST_DISK_PATTERNS_HPP

#include <cstdint>
#include <random>
#include <vector>

#include "mesh/delaunay.hpp"
#include "core/predicates.hpp"

struct Disk {
    pds::Point p;
    double r;
};

// `darts` uniform darts over the unit square, in order; O(darts * kept).
inline std::vector<Disk> rsa_disks(std::size_t darts, double (*field)(const pds::Point&), std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Disk> kept;
    for (std::size_t i = 0; i < darts; ++i) {
        const pds::Point p{u(rng), u(rng)};
        bool free = true;
        for (const Disk& d : kept)
            if (pds::compare_distance(p, d.p, d.r) < 0) {
                free = false;
                break;
            }
        if (free) kept.push_back({p, field(p)});
    }
    return kept;
}

// A 1:4 step across x = 1/2: heavy disks beside light ones hide some and
// leave others outside their own power cells.
inline double step_field(const pds::Point& p) { return p.x < 0.5 ? 0.02 : 0.08; }

inline pds::Delaunay weighted_mesh(const std::vector<Disk>& disks) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1}, true);
    dt.reserve(disks.size() + pds::Delaunay::kGhosts);
    std::uint32_t near = 0;
    for (const Disk& d : disks) near = dt.insert(d.p, d.r, near);
    return dt;
}

#endif
