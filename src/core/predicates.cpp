// predicates.cpp - filtered predicates with exact fallback (see predicates.hpp).
//
// The filters are inline in the header; these are the exact fallbacks.
#include "core/predicates.hpp"

#include "core/expansion.hpp"

namespace pds {

namespace {

template <std::size_t N>
int sign_of(const FixedExpansion<N>& e) {
    return e.sign();
}

// |p - q|^2 as an exact expansion.
FixedExpansion<16> squared_distance_exact(const Point& p, const Point& q) {
    const auto dx = exact_diff(p.x, q.x);
    const auto dy = exact_diff(p.y, q.y);
    return dx * dx + dy * dy;
}

}  // namespace

namespace predicate_detail {

int orient2d_exact(const Point& a, const Point& b, const Point& c) {
    // (a - c) x (b - c), every difference kept exactly.
    const auto acx = exact_diff(a.x, c.x);
    const auto acy = exact_diff(a.y, c.y);
    const auto bcx = exact_diff(b.x, c.x);
    const auto bcy = exact_diff(b.y, c.y);
    return sign_of(acx * bcy - acy * bcx);
}

int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
    const auto adx = exact_diff(a.x, d.x), ady = exact_diff(a.y, d.y);
    const auto bdx = exact_diff(b.x, d.x), bdy = exact_diff(b.y, d.y);
    const auto cdx = exact_diff(c.x, d.x), cdy = exact_diff(c.y, d.y);
    const auto alift = adx * adx + ady * ady;
    const auto blift = bdx * bdx + bdy * bdy;
    const auto clift = cdx * cdx + cdy * cdy;
    const auto bc = bdx * cdy - cdx * bdy;
    const auto ca = cdx * ady - adx * cdy;
    const auto ab = adx * bdy - bdx * ady;
    return sign_of(alift * bc + blift * ca + clift * ab);
}


int compare_distance_exact(const Point& p, const Point& q, double r) {
    return sign_of(squared_distance_exact(p, q) - exact_product(r, r));
}

int compare_closer_exact(const Point& p, const Point& a, const Point& b) {
    return sign_of(squared_distance_exact(p, a) - squared_distance_exact(p, b));
}

int power_test_exact(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                     const Point& d, double rd) {
    const auto adx = exact_diff(a.x, d.x), ady = exact_diff(a.y, d.y);
    const auto bdx = exact_diff(b.x, d.x), bdy = exact_diff(b.y, d.y);
    const auto cdx = exact_diff(c.x, d.x), cdy = exact_diff(c.y, d.y);
    const auto rd2 = exact_product(rd, rd);
    const auto alift = adx * adx + ady * ady - exact_product(ra, ra) + rd2;
    const auto blift = bdx * bdx + bdy * bdy - exact_product(rb, rb) + rd2;
    const auto clift = cdx * cdx + cdy * cdy - exact_product(rc, rc) + rd2;
    const auto bc = bdx * cdy - cdx * bdy;
    const auto ca = cdx * ady - adx * cdy;
    const auto ab = adx * bdy - bdx * ady;
    return sign_of(alift * bc + blift * ca + clift * ab);
}

int compare_power_exact(const Point& p, const Point& a, double ra, const Point& b, double rb) {
    return sign_of(squared_distance_exact(p, a) - exact_product(ra, ra) - squared_distance_exact(p, b) +
                   exact_product(rb, rb));
}

}  // namespace predicate_detail

}  // namespace pds
