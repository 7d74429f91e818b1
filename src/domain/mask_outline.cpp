// mask_outline.cpp - see mask_outline.hpp.
#include "domain/mask_outline.hpp"

#include "domain/polygon_rings.hpp"

namespace pds {

namespace {

// Directions of a unit side: +x, +y, -x, -y (a left turn adds one).
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

double grid_line(double lo, double hi, std::size_t i, std::size_t n) {
    if (i == 0) return lo;
    if (i == n) return hi;
    return lo + (hi - lo) * (static_cast<double>(i) / static_cast<double>(n));
}

}  // namespace

Outline mask_outline(std::size_t w, std::size_t h, const std::uint8_t* inside, const Box& box) {
    const std::size_t vw = w + 1;
    const auto in = [&](std::size_t i, std::size_t j) { return inside[j * w + i] != 0; };
    // out[v]: a bit per direction of an untraced side starting at grid vertex v.
    std::vector<std::uint8_t> out(vw * (h + 1), 0);
    bool any = false;
    for (std::size_t j = 0; j < h; ++j)
        for (std::size_t i = 0; i < w; ++i) {
            if (!in(i, j)) continue;
            any = true;
            if (j == 0 || !in(i, j - 1)) out[j * vw + i] |= 1;                   // bottom, +x
            if (i + 1 == w || !in(i + 1, j)) out[j * vw + i + 1] |= 2;           // right, +y
            if (j + 1 == h || !in(i, j + 1)) out[(j + 1) * vw + i + 1] |= 4;     // top, -x
            if (i == 0 || !in(i - 1, j)) out[(j + 1) * vw + i] |= 8;             // left, -y
        }
    if (!any) throw DomainError("the mask has no pixel inside");

    Outline o;
    const auto emit = [&](std::size_t v) {
        o.xy.push_back(grid_line(box.x0, box.x1, v % vw, w));
        o.xy.push_back(grid_line(box.y0, box.y1, v / vw, h));
    };
    for (std::size_t start = 0; start < out.size(); ++start) {
        while (out[start] != 0) {
            const std::size_t ring_first = o.xy.size();
            int dir = 0;
            while (!(out[start] >> dir & 1)) ++dir;
            const int first_dir = dir;
            int prev_dir = -1;
            std::size_t v = start;
            for (;;) {
                out[v] = static_cast<std::uint8_t>(out[v] & ~(1u << dir));
                if (dir != prev_dir) emit(v);
                prev_dir = dir;
                v = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(v) + kDx[dir] +
                                             kDy[dir] * static_cast<std::ptrdiff_t>(vw));
                if (v == start) break;
                // Left, straight, right: a side always continues at its end.
                const int turns[3] = {(dir + 1) & 3, dir, (dir + 3) & 3};
                for (int t : turns)
                    if (out[v] >> t & 1) {
                        dir = t;
                        break;
                    }
            }
            // The ring closes at its start: a start along a straight run is no corner.
            if (prev_dir == first_dir) o.xy.erase(o.xy.begin() + static_cast<std::ptrdiff_t>(ring_first),
                                                  o.xy.begin() + static_cast<std::ptrdiff_t>(ring_first) + 2);
            o.ring_ends.push_back(o.xy.size() / 2);
        }
    }
    return o;
}

}  // namespace pds
