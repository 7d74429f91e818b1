// polygon_rings.hpp - a polygon from rings given as flat x, y lists, for the
// unit tests of polygon domains.
#ifndef PDS_TEST_POLYGON_RINGS_HPP
#define PDS_TEST_POLYGON_RINGS_HPP

#include <cstddef>
#include <vector>

#include "domain/polygon.hpp"

inline pds::Polygon rings_of(const std::vector<std::vector<double>>& rings) {
    std::vector<double> xy;
    std::vector<std::size_t> ends;
    for (const auto& r : rings) {
        xy.insert(xy.end(), r.begin(), r.end());
        ends.push_back(xy.size() / 2);
    }
    return pds::Polygon(xy.data(), ends.data(), ends.size());
}

#endif
