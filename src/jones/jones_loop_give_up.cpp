// jones_loop_give_up.cpp - what the Jones loop does with a cell whose draws
// keep failing (see jones_loop.hpp): the free region is too thin for them,
// yet may hold a representable point, which the exact test can find.
#include <algorithm>
#include <cmath>

#include "cells/piece_ends.hpp"
#include "core/roundoff.hpp"
#include "jones/jones_loop.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

template <class Space, class Rule>
void JonesLoop<Space, Rule>::give_up(SiteIndex site) {
    const VertexIndex v = vertex_of(site);
    if (!cells().covered_exactly(v)) {
        // A free region the draws cannot reach (a clearance that falls short
        // of a corner of the domain by a hair) may still hold that corner,
        // an exact point: maximal means a point there. Its area is below
        // what rounding resolves, so where in it the point goes is no
        // matter of the law. The cell is measured again once it is placed.
        const Point& c = dt_.point(v);
        const double reach = 4.0 * std::max(r_, rule_.newer_radius(dt_, v, r_));
        Point corner{0.0, 0.0};
        const bool found = space_.any_corner_in(Box{c.x - reach, c.y - reach, c.x + reach, c.y + reach},
                                                [&](const Point& p) {
                                                    corner = p;
                                                    return acceptable(p, v) && still_free(p);
                                                });
        if (found || near_piece_end(v, &corner)) {
            queue_.push_back(Candidate{corner, v});
            ++stats_.corner_points;
            return;
        }
        ++stats_.gave_up_cells;
    }
    set_weight(site, 0.0);
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::near_piece_end(VertexIndex v, Point* out) const {
    // Each end, and the points a few rounding steps from it: the end was
    // computed relative to the site and moved back, each step rounded.
    // Near zero those steps are far finer than the rounding (of the site's
    // magnitude), so the end is also snapped to the grid of that magnitude,
    // which holds 0 and the domain's coarser lines.
    // A region along a side of the box holds points on that side: an end
    // within its error bound (or rounding) of it is tried on it too.
    constexpr int kSteps = 4;
    const PieceEnds ends = cells().piece_ends(v);
    const Point& c = dt_.point(v);
    const Box box = space_.clip_box();
    const auto to_side = [](double x, double lo, double hi, double tol) {
        return std::fabs(x - lo) <= tol ? lo : std::fabs(x - hi) <= tol ? hi : x;
    };
    for (int k = 0; k < ends.count(); ++k) {
        const Point e{c.x + ends[k].x, c.y + ends[k].y};
        const double mx = std::max(std::fabs(c.x), std::fabs(ends[k].x));
        const double my = std::max(std::fabs(c.y), std::fabs(ends[k].y));
        const Point snapped{on_grid_of(e.x, mx), on_grid_of(e.y, my)};
        const double err = 4.0 * ends.error(k);
        const Point sided{to_side(e.x, box.x0, box.x1, err + 16.0 * kUnitRoundoff * mx),
                          to_side(e.y, box.y0, box.y1, err + 16.0 * kUnitRoundoff * my)};
        for (const Point& b : {e, snapped, sided}) {
            for (int i = -kSteps; i <= kSteps; ++i) {
                for (int j = -kSteps; j <= kSteps; ++j) {
                    const Point p{ulps_from(b.x, i), ulps_from(b.y, j)};
                    if (acceptable(p, v) && still_free(p)) {
                        *out = p;
                        return true;
                    }
                }
            }
        }
    }
    return false;
}

#define PDS_GIVE_UP_MEMBERS(Space, Rule)                                               \
    template void JonesLoop<Space, Rule>::give_up(SiteIndex site);                    \
    template bool JonesLoop<Space, Rule>::near_piece_end(VertexIndex v, Point* out) const;
PDS_GIVE_UP_MEMBERS(PlaneSpace, OneRadius)
PDS_GIVE_UP_MEMBERS(PlaneSpace, PowerRule)
PDS_GIVE_UP_MEMBERS(TorusSpace, OneRadius)
PDS_GIVE_UP_MEMBERS(TorusSpace, PowerRule)
PDS_GIVE_UP_MEMBERS(PolygonSpace, OneRadius)
PDS_GIVE_UP_MEMBERS(PolygonSpace, PowerRule)

}  // namespace pds
