// polygon_space.hpp - the Jones loop's mesh in a polygonal domain
// (domain/polygon.hpp): the plane's mesh over the polygon's bounding box,
// with each cell cut by the outline (cells/outline_clip.hpp), points kept
// only inside the closed polygon, the first point uniform in it, and the
// certificate of the polygon (verify.hpp).
//
// Everything else is the rectangle's (plane_space.hpp): a point is one
// vertex, insertion and hand-over are the same. The outline cutter holds
// scratch space between a cell's selection and its draws; the loop reaches
// it through MeshCells, which every cell query goes through.
#ifndef PDS_POLYGON_SPACE_HPP
#define PDS_POLYGON_SPACE_HPP

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "cells/outline_clip.hpp"
#include "domain/polygon.hpp"
#include "jones/plane_space.hpp"
#include "verify/verify.hpp"

namespace pds {

class PolygonSpace : public PlaneSpace {
public:
    static constexpr bool kMeasuresSideBySide = false;  // the outline cutter keeps scratch
    PolygonSpace(const Rectangle& domain, double r, const Torus& torus, bool weighted,
                 std::shared_ptr<const Polygon> polygon)
        : PlaneSpace(domain, r, torus, weighted, nullptr),
          polygon_(std::move(polygon)),
          clip_(std::make_unique<OutlineClip>(*polygon_)) {}

    Point first_point(Rng& rng) const { return polygon_->uniform_point(rng); }
    bool inside(const Point& p) const { return polygon_->contains(p); }
    // The outline's vertices on edges near box b (may allocate).
    template <class Fn>
    bool any_corner_in(const Box& b, Fn&& fn) const {
        std::vector<std::uint32_t> edges;
        polygon_->outline_edges_near(b, edges);
        const PolygonRings& rings = polygon_->rings();
        for (std::uint32_t e : edges) {
            const Point c = rings.edge_start(e);
            if (b.contains(c) && fn(c)) return true;
        }
        return false;
    }
    OutlineClip* outline_clip() const { return clip_.get(); }

    VerifyReport verify(const Delaunay& dt, double r, const std::vector<std::size_t>* rank, std::size_t fixed) const {
        return verify_pattern(dt, Rectangle(polygon_->bounds()), r, rank, polygon_.get(), fixed);
    }

private:
    std::shared_ptr<const Polygon> polygon_;
    std::unique_ptr<OutlineClip> clip_;  // scratch, changed by const queries
};

}  // namespace pds

#endif
