// vec.hpp - the two products of plane vectors the cell geometry uses
// (circumcentres, fan pieces, chunk angles), spelled once.
#ifndef PDS_VEC_HPP
#define PDS_VEC_HPP

#include "core/point.hpp"

namespace pds {

inline double cross(const Point& a, const Point& b) { return a.x * b.y - a.y * b.x; }
inline double dot(const Point& a, const Point& b) { return a.x * b.x + a.y * b.y; }

}  // namespace pds

#endif
