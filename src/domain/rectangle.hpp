// rectangle.hpp - the domain the sampler fills: the closed axis-aligned
// rectangle [x0, x1] x [y0, y1].
//
// A domain answers what the sampler asks of the region it fills, and the
// rest of the library asks only this:
//   contains(p)         the closed domain: its boundary belongs to it;
//   bounds()            the smallest box holding it: the mesh's ghosts and
//                       the dart grid cover it, and the cell pipeline clips
//                       each Voronoi cell to it (cells/cell_stream.hpp clips
//                       to a box's four sides: for a rectangle that is the
//                       exact clip);
//   area(), perimeter() the expected count of a maximal pattern;
//   count_bound(r)      a rigorous bound on any pattern's size (Oler);
//   uniform_point(rng)  a point uniform in the domain (the first point);
//   scaled(k)           the same domain times 2^k, exactly (frame.hpp);
//   uncovered_side()    the certificate that its boundary is covered
//                       (rectangle_boundary.cpp).
// A new kind of domain is one more type with these functions.
#ifndef PDS_RECTANGLE_HPP
#define PDS_RECTANGLE_HPP

#include <algorithm>
#include <cmath>

#include "core/point.hpp"
#include "core/rng.hpp"

namespace pds {

class Delaunay;

class Rectangle {
public:
    Rectangle() = default;
    // A box as a domain (the internal frame, or the user's).
    Rectangle(const Box& box) : box_(box) {}  // NOLINT: a box is a rectangle

    const Box& bounds() const { return box_; }
    bool contains(const Point& p) const { return box_.contains(p); }
    double area() const { return box_.width() * box_.height(); }
    double perimeter() const { return 2.0 * (box_.width() + box_.height()); }
    // The diagonal: no two points of the domain are farther apart.
    double diameter() const { return box_.diagonal(); }
    // Oler (1961): points at mutual distance >= r in a convex region of area
    // A and perimeter P number at most 2A/(sqrt(3) r^2) + P/(2r) + 1.
    double count_bound(double r) const {
        const double w = box_.width() / r, h = box_.height() / r;
        return 2.0 / std::sqrt(3.0) * w * h + (w + h) + 1.0;
    }
    // Uniform in the domain, from two draws of the generator (x, then y);
    // rounding may not leave it.
    Point uniform_point(Rng& rng) const {
        Point p{box_.x0 + rng.next_double() * box_.width(), box_.y0 + rng.next_double() * box_.height()};
        p.x = std::min(p.x, box_.x1);
        p.y = std::min(p.y, box_.y1);
        return p;
    }
    // The largest |coordinate| of the domain.
    double largest_magnitude() const { return box_.largest_magnitude(); }
    Rectangle scaled(int k) const {
        return Rectangle(Box{std::ldexp(box_.x0, k), std::ldexp(box_.y0, k), std::ldexp(box_.x1, k),
                             std::ldexp(box_.y1, k)});
    }

    // The certificate of maximality on the boundary: the name of a side
    // ("bottom", "top", "left", "right") some point of which lies farther
    // than its radius (r, or each vertex's own on a weighted mesh) from
    // every vertex of dt, or nullptr when every side is covered. Exact.
    const char* uncovered_side(const Delaunay& dt, double r) const;

private:
    Box box_{0.0, 0.0, 1.0, 1.0};
};

}  // namespace pds

#endif
