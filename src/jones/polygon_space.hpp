// polygon_space.hpp - the Jones loop's mesh in a polygonal domain
// (domain/polygon.hpp): the plane's mesh over the polygon's bounding box,
// with each cell cut by the outline (cells/outline_clip.hpp), points kept
// only inside the closed polygon, the first point uniform in it, and the
// certificate of the polygon (verify.hpp).
//
// Everything else is the rectangle's (plane_space.hpp): a point is one
// vertex, insertion and hand-over are the same. The outline cutter holds
// scratch space between a cell's selection and its draws; the loop reaches
// it through MeshCells, which every cell query goes through; workers that
// measure side by side each have their own.
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
    // Each worker measures with its own cutter (it keeps scratch).
    static constexpr bool kMeasuresSideBySide = true;
    PolygonSpace(const Rectangle& domain, double r, const Torus& torus, bool weighted,
                 std::shared_ptr<const Polygon> polygon)
        : PlaneSpace(domain, r, torus, weighted, nullptr),
          polygon_(std::move(polygon)),
          clips_(1) {
        clips_[0] = std::make_unique<OutlineClip>(*polygon_);
    }

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
    OutlineClip* outline_clip(unsigned w = 0) const { return clips_[w].get(); }
    // Cutters for n workers, made before they are needed (they reserve
    // scratch: the loop's measuring must not allocate).
    void set_workers(unsigned n) {
        clips_.reserve(n);
        while (clips_.size() < n) clips_.push_back(std::make_unique<OutlineClip>(*polygon_));
    }

    VerifyReport verify(const Delaunay& dt, double r, const std::vector<std::size_t>* rank, std::size_t fixed) const {
        return verify_pattern(dt, Rectangle(polygon_->bounds()), r, rank, polygon_.get(), fixed);
    }

private:
    std::shared_ptr<const Polygon> polygon_;
    std::vector<std::unique_ptr<OutlineClip>> clips_;  // one a worker; scratch, changed by const queries
};

}  // namespace pds

#endif
