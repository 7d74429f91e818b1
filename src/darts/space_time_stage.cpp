// space_time_stage.cpp - the epochs of the space-time dart process (see
// space_time_stage.hpp).
#include "darts/space_time_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "darts/jones_of_points.hpp"
#include "darts/space_time_band.hpp"
#include "darts/sub_square_raster.hpp"
#include "jones/jones_stage.hpp"

namespace pds {

namespace {

// Darts per cell and epoch (the mean of each cell's Poisson count): small,
// so an epoch's candidates seldom reach one another (most are decided at a
// glance) and a dart an earlier point covers is dropped by the grid, which
// is cheaper than by resolving it (measured: 0.125 against 0.25 and 0.5).
constexpr double kDartsPerCell = 0.125;
// The stage ends after an epoch in which fewer than this share of the darts
// (in active cells) became points (measured at 10^6 points against 0.02 and
// 0.1).
constexpr double kStopAcceptance = 0.05;
// A band is at least this many rows: thinner ones would share most of
// their reads with their neighbours.
constexpr std::int64_t kMinBandRows = 8;
// Cells ahead whose grid words are asked for before they are read.
constexpr std::size_t kAhead = 8;
// Epochs at most: past them the Jones loop is far cheaper anyway.
constexpr std::size_t kMaxEpochs = 65535;
// Mixed into the seed for the rows' streams, which the cells' never meet.
constexpr std::uint64_t kRowSalt = 0xA5E1D0C3B2F49687ull;

enum : std::uint8_t { kUndecided = 0, kAccepted = 1, kRejected = 2 };

}  // namespace

SpaceTimeDartStage::SpaceTimeDartStage(const Rectangle& domain, std::shared_ptr<const Polygon> polygon, double radius,
                                       std::uint64_t seed, const Torus& torus)
    : domain_(domain),
      polygon_(std::move(polygon)),
      r_(radius),
      seed_(seed),
      torus_(torus),
      grid_(domain.bounds(), radius, torus),
      gaps_(kDartsPerCell) {
    const Box& box = grid_.box();
    curve_ = CurveOrder(box, grid_.side_x(), grid_.side_y(), grid_.cols(), grid_.rows());
    const std::size_t cells = grid_.cell_count();
    if (cells >= SpaceTimeGrid::kEpochFlag) throw std::bad_alloc();  // cells are 31-bit ids
    masks_.assign(cells, 0);
    const std::int64_t last_col = static_cast<std::int64_t>(grid_.cols()) - 1, last_row = static_cast<std::int64_t>(grid_.rows()) - 1;
    if (!torus_.on()) {
        // The last column's and row's parts beyond the box (on the torus the
        // cells divide the periods).
        for (std::int64_t row = 0; row <= last_row; ++row)
            masks_[static_cast<std::size_t>(row * (last_col + 1) + last_col)] = grid_.outside(last_col, row, box);
        for (std::int64_t col = 0; col <= last_col; ++col)
            masks_[static_cast<std::size_t>(last_row * (last_col + 1) + col)] |= grid_.outside(col, last_row, box);
    }
    if (polygon_) {
        inside_.assign(cells, 0);
        rastered_ = classify_sub_squares(*polygon_, box.x0, box.y0, grid_.side_x(), grid_.cols(), grid_.rows(), masks_,
                                         inside_);
        if (!rastered_) return;
    }
    list_active_cells();
}

void SpaceTimeDartStage::list_active_cells() {
    // The active cells: those with a sub-square in the domain, not known covered.
    const std::size_t cells = grid_.cell_count();
    std::size_t active = 0;
    for (std::size_t c = 0; c < cells; ++c) active += masks_[c] != SpaceTimeGrid::kAllCovered;
    active_.resize(active);
    active = 0;
    for (std::size_t c = 0; c < cells; ++c)
        if (masks_[c] != SpaceTimeGrid::kAllCovered) active_[active++] = static_cast<std::uint32_t>(c);
}

bool SpaceTimeDartStage::hold_fixed(const std::vector<Point>& points, const std::vector<double>& values,
                                    const PointRadii& radii, double new_value) {
    if (epoch_ != 0 || !points_.empty()) throw std::logic_error("hold_fixed after the first epoch");
    std::vector<double> clearances(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) clearances[k] = radii.radius_of(values[k]);
    // The disks' bounding boxes may span a few times the grid (one covering
    // the domain spans it once); beyond, the Jones loop alone is cheaper.
    if (!fixed_disks_.build(grid_, points, clearances, masks_, 4 * grid_.cell_count() + (std::size_t{1} << 20)))
        return false;
    list_active_cells();
    points_ = points;
    values_ = values;
    fixed_ = points.size();
    new_value_ = new_value;
    radii_.emplace(radii);
    return true;
}

SpaceTimeDartStage::~SpaceTimeDartStage() = default;

void SpaceTimeDartStage::reserve(std::size_t points) {
    points_.reserve(points);
    if (fixed_ != 0) values_.reserve(points);
    curve_.reserve(points);
    grid_.reserve(points);
}

bool SpaceTimeDartStage::has_room_for(std::size_t points) const {
    return points_.capacity() >= points && (fixed_ == 0 || values_.capacity() >= points) &&
           curve_.has_room_for(points);
}

const Point* SpaceTimeDartStage::next(Rng&) {
    if (next_pending_ < pending_.size()) return &pending_[next_pending_];
    while (!over_)
        if (run_epoch()) return &pending_[next_pending_];
    return nullptr;
}

bool SpaceTimeDartStage::run_epoch() {
    if (active_.empty()) over_ = true;
    if (over_) return false;
    // Threads live for one epoch (a few milliseconds at least; starting
    // them costs tens of microseconds): none is left between the calls.
    WorkerPool pool(threads_);
    const unsigned workers = pool.size();
    // Bands of rows, a few per worker: their count changes the work's
    // split, never its outcome.
    const auto rows = static_cast<std::int64_t>(grid_.rows());
    const auto cols = static_cast<std::uint64_t>(grid_.cols());
    const std::size_t n = std::max<std::size_t>(
        1, std::min<std::size_t>(workers, static_cast<std::size_t>(rows / kMinBandRows)));
    bands_.resize(n);
    for (std::size_t b = 0; b < n; ++b) {
        Band& band = bands_[b];
        band.r0 = rows * static_cast<std::int64_t>(b) / static_cast<std::int64_t>(n);
        band.r1 = rows * static_cast<std::int64_t>(b + 1) / static_cast<std::int64_t>(n);
        const auto first = [&](std::int64_t row) {
            const std::uint64_t id = static_cast<std::uint64_t>(row) * cols;
            return static_cast<std::size_t>(std::lower_bound(active_.begin(), active_.end(), id) - active_.begin());
        };
        band.a0 = first(band.r0);
        band.a1 = first(band.r1);
    }
    const auto each_band = [&](void (SpaceTimeDartStage::*step)(Band&)) {
        pool.run([&](unsigned w) {
            for (std::size_t b = w; b < n; b += workers) (this->*step)(bands_[b]);
        });
    };
    // (1) Darts and candidates; every allocation of the epoch happens here,
    // before the grid is written (std::bad_alloc leaves the stage as it was).
    each_band(&SpaceTimeDartStage::draw);
    std::size_t candidates = 0, thrown = 0;
    for (const Band& band : bands_) {
        candidates += band.cands.size();
        thrown += band.thrown;
    }
    pending_.clear();
    pending_.reserve(candidates);
    pool.run([&](unsigned w) {
        for (std::size_t b = w; b < n; b += workers) list_candidates(bands_[b], static_cast<std::uint32_t>(b), true);
    });
    // (2) The outcomes; (3) numbered by time, into the grid; (4) the cells left.
    try {
        each_band(&SpaceTimeDartStage::resolve);
    } catch (...) {
        // Only decide()'s stack can fail to grow: take the lists out again.
        pool.run([&](unsigned w) {
            for (std::size_t b = w; b < n; b += workers) list_candidates(bands_[b], 0, false);
        });
        throw;
    }
    merge();
    each_band(&SpaceTimeDartStage::write_points);
    each_band(&SpaceTimeDartStage::drop_covered);
    std::size_t kept = 0;
    for (const Band& band : bands_) {
        std::memmove(active_.data() + kept, active_.data() + band.a0, band.kept * sizeof(std::uint32_t));
        kept += band.kept;
    }
    active_.resize(kept);
    ++epoch_;
    if (static_cast<double>(pending_.size()) < kStopAcceptance * static_cast<double>(thrown) || epoch_ == kMaxEpochs)
        over_ = true;
    return !pending_.empty();
}

void SpaceTimeDartStage::draw(Band& band) {
    band.cands.clear();
    band.thrown = 0;
    // About kDartsPerCell a cell land free early on, fewer later.
    band.cands.reserve(static_cast<std::size_t>(static_cast<double>(band.a1 - band.a0) * (kDartsPerCell * 1.2)) + 64);
    // First which active cells draw darts: most draw none in an epoch, so
    // each row's stream gives the gaps between those that do
    // (core/poisson_gaps.hpp), and only those need their grid block and
    // their own stream, which gives their count and their darts.
    const std::uint64_t salted = SpaceTimeStream::salted(seed_), salted_rows = SpaceTimeStream::salted(seed_ ^ kRowSalt);
    const auto cols = static_cast<std::uint32_t>(grid_.cols());
    band.darting.clear();
    band.darting.reserve(static_cast<std::size_t>(static_cast<double>(band.a1 - band.a0) * (kDartsPerCell * 1.5)) + 64);
    for (std::size_t i = band.a0; i < band.a1;) {
        const std::uint32_t row = active_[i] / cols;
        const auto row_end = std::lower_bound(active_.begin() + static_cast<std::ptrdiff_t>(i),
                                              active_.begin() + static_cast<std::ptrdiff_t>(std::min(band.a1, i + cols)),
                                              static_cast<std::uint64_t>(row + 1) * cols);
        const auto end = static_cast<std::size_t>(row_end - active_.begin());
        SpaceTimeStream row_stream(salted_rows, row, epoch_);
        for (std::size_t j = i + gaps_.gap(row_stream); j < end; j += 1 + gaps_.gap(row_stream)) {
            SpaceTimeStream stream(salted, active_[j], epoch_);
            const unsigned darts = gaps_.count_of_darting(stream);
            band.thrown += darts;
            band.darting.push_back(Band::Darting{stream, active_[j], darts});
        }
        i = end;
    }
    const double side_x = grid_.side_x(), side_y = grid_.side_y();
    const auto stride = static_cast<std::ptrdiff_t>(grid_.stride());
    const Box& box = grid_.box();
    const std::size_t darting = band.darting.size();
    for (std::size_t i = 0; i < darting; ++i) {
        // Late in the stage these cells are scattered: their blocks' cache
        // misses overlap when asked for a few cells ahead.
        if (i + kAhead < darting) {
            const std::uint32_t ahead = band.darting[i + kAhead].cell;
            grid_.prefetch_block(ahead % cols, ahead / cols);
        }
        const std::uint32_t cell = band.darting[i].cell;
        const std::int64_t col = cell % cols, row = cell / cols;
        SpaceTimeStream stream = band.darting[i].stream;
        const unsigned darts = band.darting[i].darts;
        std::uint16_t& mask = masks_[cell];
        for (unsigned k = 0; k < darts; ++k) {
            const double t = stream.next_double();
            const double u = stream.next_double(), v = stream.next_double();
            Point p{grid_.cell_x0(col) + u * side_x, grid_.cell_y0(row) + v * side_y};
            // A dart in a sub-square known covered is covered; one known
            // outside the domain is outside.
            const unsigned sub = SpaceTimeGrid::sub_square(u, v);
            if (mask >> sub & 1u) continue;
            if (torus_.on()) {
                // On the torus grid (torus.hpp), in the fundamental domain:
                // one rounded onto its far side is dropped, as the near side
                // already holds that place.
                p = Point{Torus::snap(p.x), Torus::snap(p.y)};
                if (!(p.x < box.x1 && p.y < box.y1)) continue;
            } else if (!domain_.contains(p)) {
                continue;
            }
            if (polygon_ && !(inside_[cell] >> sub & 1u) && !polygon_->contains(p)) continue;
            if (fixed_disks_.listed(cell) && fixed_disks_.covers(p, cell)) continue;
            // Only the earlier epochs' points are in the grid now, numbered.
            const SpaceTimeGrid::Aim a = grid_.aim_in(p, col, row);  // an active cell holds no point
            const auto covers = [&](int di, int dj) {
                const SpaceTimeGrid::Word w = grid_.load(a.cell + static_cast<std::size_t>(di * stride + dj));
                if (w == 0) return false;
                const int near = grid_.rounded_within(p, grid_.rounded(w, a.col + dj, a.row + di));
                if (near != 0) return near > 0;
                int si, sj;  // a point read in the torus's padding is its copy
                grid_.copy_shift(a.col, a.row, dj, di, &si, &sj);
                return compare_distance(p, torus_.shifted(numbered_point(SpaceTimeGrid::index_of(w)), si, sj), r_) < 0;
            };
            if (block_covers(a.x_lo, a.x_hi, a.y_lo, a.y_hi, covers)) {
                // Covered: the disks that cover this dart may cover whole
                // sub-squares of its cell. The certificate is paid for by
                // the covered darts, where it is likely to pass.
                mask = static_cast<std::uint16_t>(mask | grid_.covered_by_disks_at(p, a, box));
                if (mask == SpaceTimeGrid::kAllCovered) break;  // its other darts are covered too
                continue;
            }
            band.cands.push_back(Candidate{t, p, cell, k});
        }
    }
    const std::size_t m = band.cands.size();
    if (band.state_room < m) {
        band.state.reset(new std::atomic<std::uint8_t>[m]);
        band.state_room = m;
    }
    for (std::size_t i = 0; i < m; ++i) band.state[i].store(kUndecided, std::memory_order_relaxed);
    band.stack.reserve(1024);
    band.accepted.clear();
    band.accepted.reserve(m);
    band.sorted.reserve(m);  // sort_by_time()'s scratch: resolve() allocates nothing
    band.starts.reserve(m + 1);
}

void SpaceTimeDartStage::list_candidates(Band& band, std::uint32_t band_index, bool write) {
    // A cell's candidates are consecutive (drawn cell by cell); an empty
    // cell's word holds their list while the epoch is resolved.
    const auto cols = static_cast<std::uint32_t>(grid_.cols());
    for (std::size_t i = 0; i < band.cands.size();) {
        const std::uint32_t cell = band.cands[i].cell;
        std::size_t j = i + 1;
        while (j < band.cands.size() && band.cands[j].cell == cell) ++j;
        grid_.store_with_copies(cell % cols, cell / cols,
                                write ? SpaceTimeGrid::list_word(band_index, static_cast<std::uint32_t>(i),
                                                                 static_cast<std::uint32_t>(j - i))
                                      : 0);
        i = j;
    }
}

void SpaceTimeDartStage::resolve(Band& band) {
    const std::size_t b = static_cast<std::size_t>(&band - bands_.data());
    for (std::size_t k = 0; k < band.cands.size(); ++k)
        if (decide(b, k, band.stack)) band.accepted.push_back(Band::Accepted{band.cands[k].t, static_cast<std::uint32_t>(k), 0});
    // By time, for merge(): each band sorts its own, side by side.
    sort_by_time(band);
}

bool SpaceTimeDartStage::decide(std::size_t b0, std::size_t k0, std::vector<std::uint64_t>& stack) {
    const auto state = [&](std::size_t b, std::size_t k) -> std::atomic<std::uint8_t>& { return bands_[b].state[k]; };
    const std::uint8_t known = state(b0, k0).load(std::memory_order_acquire);
    if (known != kUndecided) return known == kAccepted;
    const auto cols = static_cast<std::uint32_t>(grid_.cols());
    const auto stride = static_cast<std::ptrdiff_t>(grid_.stride());
    constexpr std::uint64_t kNone = ~std::uint64_t{0};
    stack.clear();
    stack.push_back((std::uint64_t{b0} << 56) | k0);
    while (!stack.empty()) {
        const auto b = static_cast<std::size_t>(stack.back() >> 56);
        const auto k = static_cast<std::size_t>(stack.back() & ((std::uint64_t{1} << 56) - 1));
        if (state(b, k).load(std::memory_order_acquire) != kUndecided) {
            stack.pop_back();
            continue;
        }
        // c is rejected iff an earlier candidate within R is accepted: look
        // for one decided accepted, else ask the first undecided one first.
        const Candidate& c = bands_[b].cands[k];
        const SpaceTimeGrid::Aim a = grid_.aim_in(c.p, c.cell % cols, c.cell / cols);
        bool covered = false;
        std::uint64_t ask = kNone;
        for (int di = a.y_lo; di <= a.y_hi && !covered; ++di) {
            for (int dj = a.x_lo; dj <= a.x_hi && !covered; ++dj) {
                const SpaceTimeGrid::Word w = grid_.load(a.cell + static_cast<std::size_t>(di * stride + dj));
                if (!SpaceTimeGrid::is_list(w)) continue;
                const std::uint32_t ob = SpaceTimeGrid::list_band(w), first = SpaceTimeGrid::list_first(w);
                const std::uint32_t last = first + SpaceTimeGrid::list_count(w);
                int si, sj;  // a list read in the torus's padding is its cell's, shifted
                grid_.copy_shift(a.col, a.row, dj, di, &si, &sj);
                for (std::uint32_t q = first; q < last; ++q) {
                    const Candidate& o = bands_[ob].cands[q];
                    if (!earlier(o, c) || compare_distance(c.p, torus_.shifted(o.p, si, sj), r_) >= 0) continue;
                    const std::uint8_t s = state(ob, q).load(std::memory_order_acquire);
                    if (s == kAccepted) {
                        covered = true;
                        break;
                    }
                    if (s == kUndecided && ask == kNone) ask = (std::uint64_t{ob} << 56) | q;
                }
            }
        }
        if (covered) {
            state(b, k).store(kRejected, std::memory_order_release);
            stack.pop_back();
        } else if (ask != kNone) {
            stack.push_back(ask);  // earlier than c: the chain ends
        } else {
            state(b, k).store(kAccepted, std::memory_order_release);
            stack.pop_back();
        }
    }
    return state(b0, k0).load(std::memory_order_acquire) == kAccepted;
}

void SpaceTimeDartStage::hand_over_to(JonesStage& jones, const Poll& poll) {
    // Everything the epochs used goes before the Jones stage's mesh grows.
    over_ = true;
    grid_.release();
    std::vector<Band>().swap(bands_);
    std::vector<std::uint32_t>().swap(active_);
    std::vector<std::uint16_t>().swap(masks_);
    std::vector<std::uint16_t>().swap(inside_);
    std::vector<Point>().swap(pending_);
    fixed_disks_ = FixedDisks{};
    next_pending_ = 0;
    // The fixed points first, in their order; the Jones stage builds the
    // others' mesh whole, then inserts them (plane_space.hpp).
    const std::uint32_t* order = curve_.order(points_, threads_, fixed_);
    poll();
    jones.set_fixed(fixed_);
    jones.adopt(points_, order, fixed_ != 0 ? &values_ : nullptr, poll, MeshBuild::whole);
    jones.carry_darts(SpaceTimeStream::salted(seed_), epoch_);
}

std::unique_ptr<JonesStage> SpaceTimeDartStage::jones_of_points() const {
    std::unique_ptr<JonesStage> jones = pds::jones_of_points(domain_, polygon_, r_, torus_, radii_ ? &*radii_ : nullptr,
                                                             points_, fixed_ != 0 ? &values_ : nullptr, curve_);
    jones->set_fixed(fixed_);
    return jones;
}

double SpaceTimeDartStage::free_area() const { return jones_of_points()->free_area(); }

VerifyReport SpaceTimeDartStage::verify() const { return jones_of_points()->verify(); }

}  // namespace pds
