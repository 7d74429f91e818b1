// sub_square_raster.cpp - see sub_square_raster.hpp.
#include "darts/sub_square_raster.hpp"

#include "darts/polygon_raster.hpp"

namespace pds {

bool classify_sub_squares(const Polygon& polygon, double x0, double y0, double side, std::size_t cols,
                          std::size_t rows, std::vector<std::uint16_t>& outside, std::vector<std::uint16_t>& inside) {
    const double quarter = side / 4.0;
    PolygonRaster raster;
    if (!raster.build(polygon, x0, quarter, 4 * cols, y0, quarter, 4 * rows,
                      raster_band_budget(polygon, quarter * quarter)))
        return false;
    // Each run's sub-squares into `inside` (all of them, or the inside
    // runs' only): no scratch as large as the grid, whose release would
    // make the allocator keep later blocks of that size on its heap.
    const auto mark = [&](bool inside_runs_only) {
        raster.for_each_run([&](std::size_t row4, std::size_t lo4, std::size_t hi4, bool in) {
            if (inside_runs_only && !in) return;
            const std::size_t row = row4 / 4, b = row4 % 4;
            for (std::size_t c4 = lo4; c4 <= hi4; ++c4) {
                const std::size_t cell = row * cols + c4 / 4;
                inside[cell] = static_cast<std::uint16_t>(inside[cell] | 1u << (4 * b + c4 % 4));
            }
        });
    };
    // The sub-squares the runs hold; the rest are outside.
    mark(false);
    for (std::size_t c = 0; c < cols * rows; ++c) {
        outside[c] = static_cast<std::uint16_t>(outside[c] | ~inside[c]);
        inside[c] = 0;
    }
    mark(true);
    return true;
}

}  // namespace pds
