// space_time_grid.cpp - see space_time_grid.hpp.
#include "darts/space_time_grid.hpp"

#include <algorithm>
#include <new>

namespace pds {

SpaceTimeGrid::SpaceTimeGrid(const Box& box, double radius, const Torus& torus) : box_(box), torus_(torus), r_(radius) {
    using namespace darts;
    // On the torus, as dart_grid.hpp's: the cells divide the periods
    // (grid_axis), and span the fundamental domain.
    const bool on = torus_.on();
    if (on) box_ = Box{torus_.x0, torus_.y0, torus_.x0 + torus_.px, torus_.y0 + torus_.py};
    x_ = grid_axis(on ? torus_.px : box_.width(), cell_side(radius), radius, on);
    y_ = grid_axis(on ? torus_.py : box_.height(), cell_side(radius), radius, on);
    cols_ = x_.count;
    rows_ = y_.count;
    r2_low_ = radius * radius * (1.0 - kFilterSlack);
    r2_high_ = radius * radius * (1.0 + kFilterSlack);
    // A sub-square is certified when its farthest corner lies this far
    // inside R: far above the rounding of the corners and distances.
    const double cover = radius - 4.0 * std::max(x_.step, y_.step);
    r2_cover_ = cover * cover;
    stride_ = cols_ + 2 * kPad;
    const std::size_t padded_rows = rows_ + 2 * kPad;
    if (padded_rows > static_cast<std::size_t>(-1) / stride_) throw std::bad_alloc();
    cells_ = DenseCells(stride_ * padded_rows);
}

SpaceTimeGrid::Aim SpaceTimeGrid::aim_in(const Point& p, std::int64_t col, std::int64_t row) const {
    using darts::kPad;
    Aim a;
    const double fx = (p.x - box_.x0) * x_.inv, fy = (p.y - box_.y0) * y_.inv;
    a.col = col;
    a.row = row;
    a.cell = padded(col, row);
    a.x_lo = block_offset(fx - x_.reach, a.col, kPad);
    a.x_hi = block_offset(fx + x_.reach, a.col, kPad);
    a.y_lo = block_offset(fy - y_.reach, a.row, kPad);
    a.y_hi = block_offset(fy + y_.reach, a.row, kPad);
    return a;
}

void SpaceTimeGrid::store_copies(std::int64_t col, std::int64_t row, Word w) {
    using darts::kPad;
    // The copies one period away that fall in the padding (with few cells
    // along an axis, a cell has copies on both sides).
    const auto cols = static_cast<std::int64_t>(cols_), rows = static_cast<std::int64_t>(rows_);
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            if (i == 0 && j == 0) continue;
            const std::int64_t x = col + i * cols, y = row + j * rows;
            if (x < -kPad || x >= cols + kPad || y < -kPad || y >= rows + kPad) continue;
            cells_.store(padded(x, y), w);
        }
}

namespace {

// The sides of a cell's 4 x 4 sub-squares, clipped to the domain: an empty
// interval is the part of an edge cell beyond it.
void sub_square_sides(double x0, double y0, double side_x, double side_y, const Box& domain, double* xs, double* ys) {
    for (int k = 0; k <= 4; ++k) {
        xs[k] = std::min(std::max(x0 + k * (side_x / 4.0), domain.x0), domain.x1);
        ys[k] = std::min(std::max(y0 + k * (side_y / 4.0), domain.y0), domain.y1);
    }
}

}  // namespace

std::uint16_t SpaceTimeGrid::outside(std::int64_t col, std::int64_t row, const Box& domain) const {
    double xs[5], ys[5];
    sub_square_sides(cell_x0(col), cell_y0(row), x_.side, y_.side, domain, xs, ys);
    std::uint16_t mask = 0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a)
            if (!(xs[a] < xs[a + 1]) || !(ys[b] < ys[b + 1])) mask = static_cast<std::uint16_t>(mask | 1u << (4 * b + a));
    return mask;
}

std::uint16_t SpaceTimeGrid::covered_by_disks_at(const Point& p, const Aim& a, const Box& domain) const {
    std::uint16_t mask = 0;
    for (int di = a.y_lo; di <= a.y_hi; ++di)
        for (int dj = a.x_lo; dj <= a.x_hi; ++dj) {
            const Word w = load(a.cell + static_cast<std::size_t>(di * static_cast<std::ptrdiff_t>(stride_) + dj));
            if (w == 0) continue;
            const Point q = rounded(w, a.col + dj, a.row + di);
            if (rounded_within(p, q) >= 0) mask = static_cast<std::uint16_t>(mask | covered_by(a.col, a.row, q, domain));
        }
    return mask;
}

std::uint16_t SpaceTimeGrid::covered_by(std::int64_t col, std::int64_t row, const Point& q, const Box& domain) const {
    return covered_within(col, row, q, r_, r2_cover_, domain);
}

std::uint16_t SpaceTimeGrid::covered_by_disk(std::int64_t col, std::int64_t row, const Point& q, double radius,
                                             const Box& domain) const {
    const double cover = radius - 4.0 * std::max(x_.step, y_.step);
    return cover > 0.0 ? covered_within(col, row, q, radius, cover * cover, domain) : 0;
}

std::uint16_t SpaceTimeGrid::covered_within(std::int64_t col, std::int64_t row, const Point& q, double radius,
                                            double cover2, const Box& domain) const {
    // A sub-square's farthest corner is no nearer than its centre: none is
    // covered when every centre lies beyond R (the usual case for the
    // cells at the block's corners).
    const double qx = x_.side / 4.0, qy = y_.side / 4.0;
    const double cx = cell_x0(col) + 2.0 * qx, cy = cell_y0(row) + 2.0 * qy;
    const double ex = std::max(std::fabs(q.x - cx) - 1.5 * qx, 0.0), ey = std::max(std::fabs(q.y - cy) - 1.5 * qy, 0.0);
    if (ex * ex + ey * ey >= radius * radius) return 0;
    double xs[5], ys[5];
    sub_square_sides(cell_x0(col), cell_y0(row), x_.side, y_.side, domain, xs, ys);
    // A sub-square lies in the disk iff its farthest corner does: the
    // farther side along x and along y, apart.
    double fx[4], fy[4];
    for (int k = 0; k < 4; ++k) {
        const double ax = std::max(std::fabs(xs[k] - q.x), std::fabs(xs[k + 1] - q.x));
        const double ay = std::max(std::fabs(ys[k] - q.y), std::fabs(ys[k + 1] - q.y));
        fx[k] = ax * ax;
        fy[k] = ay * ay;
    }
    std::uint16_t mask = 0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a)
            if (fx[a] + fy[b] < cover2) mask = static_cast<std::uint16_t>(mask | 1u << (4 * b + a));
    return mask;
}

}  // namespace pds
