// polygon_rings.hpp - a polygon from rings given as flat x, y lists, for the
// unit tests of polygon domains.
#ifndef PDS_TEST_POLYGON_RINGS_HPP
#define PDS_TEST_POLYGON_RINGS_HPP

#include <cstddef>
#include <vector>

#include "domain/polygon.hpp"

// The rings as pds_set_polygon takes them: x y interleaved, and ring ends.
struct FlatRings {
    std::vector<double> xy;
    std::vector<std::size_t> ends;
};

inline FlatRings flat_rings(const std::vector<std::vector<double>>& rings) {
    FlatRings flat;
    for (const auto& r : rings) {
        flat.xy.insert(flat.xy.end(), r.begin(), r.end());
        flat.ends.push_back(flat.xy.size() / 2);
    }
    return flat;
}

inline pds::Polygon rings_of(const std::vector<std::vector<double>>& rings) {
    const FlatRings flat = flat_rings(rings);
    return pds::Polygon(flat.xy.data(), flat.ends.data(), flat.ends.size());
}

// The bench's comb: a base 0.1 tall and `teeth` teeth 0.9 long, 0.3 of
// their period wide.
inline std::vector<double> comb(int teeth) {
    const double step = 1.0 / teeth, width = 0.3 / teeth;
    std::vector<double> xy{0, 0, 1, 0, 1, 0.1};
    for (int i = teeth - 1; i >= 0; --i) {
        const double left = i * step, right = left + width;
        xy.insert(xy.end(), {right, 0.1, right, 1.0, left, 1.0});
        if (i > 0) xy.insert(xy.end(), {left, 0.1});
    }
    return xy;
}

#endif
