// region_darts.hpp - the space-time dart process carried on after the
// hand-over, with darts drawn only where a point can still go: inside the
// free regions the Jones loop's cells already describe.
//
// Why it is exact. The parallel opening (darts/space_time_stage.hpp) is a
// Poisson process of darts on domain x time, decided greedily in order of
// time. A dart that lands outside the free region is covered and never
// becomes a point, so the process restricted to the free region, at the
// same rate (one dart per unit area and time), gives the same points. After
// the hand-over each site's cell carries an upper bound U on its free area
// (the loop's lazy weights, jones_loop.hpp). In an epoch of length dt a cell
// gets a Poisson(U dt) number of darts, each kept with probability A / U
// (its target u U falls inside the exact free area A, as in a selection)
// and then drawn uniformly from the free region (piece by area, point by
// rejection); so the kept darts are a Poisson(A dt) number, uniform over the
// cell's free region, with uniform times in the epoch: together, the
// restricted process. The epoch's darts are decided greedily in order of
// time: a dart becomes a point iff no earlier dart of the epoch within R did
// (each one was free of the older points when drawn). So every point is
// uniform over the free region given the points before it (RSA). The
// process hands over to the loop's own draws after an epoch that placed few
// points (a stopping time), and the loop goes on with the same law.
//
// Why it is parallel and deterministic. A cell's darts in epoch e come from
// a stream keyed by (seed, site, e); a site's number never depends on the
// threads (points are inserted in order of time). The cells are drawn side
// by side in fixed blocks, each block writing its own list; the lists are
// joined in block order, and the decision reads times only. The scan of
// the active list (its bounds summed in its order), the decision and the
// insertions run on the caller's thread; in the plane, with threads, the
// scan runs beside the last epoch's insertions instead (active_scan.hpp).
//
// With a field. A new point keeps the later ones out of its own disk, whose
// radius the field gives at the point. A dart is then free iff no earlier
// accepted dart of the epoch holds it in its disk; the field is asked only
// at the darts accepted, in order of time (they become the points, in that
// order), and their values are kept for the insertions. The grid's cells
// are 2 rmax wide. A field that refuses a point (DartField::value_at
// throws) leaves the epoch undecided: a later call draws and decides it
// again, and is refused at the same dart.
//
// Memory. An epoch is all or nothing: its darts and its tightened bounds are
// written to buffers and committed once all of them exist; std::bad_alloc
// leaves the process as before the epoch, so a later call draws the same.
// Besides the active list (4 bytes a free cell) and an epoch's darts, the
// decision keeps a grid of one word per cell of side 2R (about 1.5 bytes a
// point), allocated at the first epoch; about 8 bytes a point in all.
#ifndef PDS_REGION_DARTS_HPP
#define PDS_REGION_DARTS_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/torus.hpp"

namespace pds {

// A field's radius at the accepted darts (the Jones loop's rule).
class DartField {
public:
    // The field's value at p; may throw (a value the field refuses).
    virtual double value_at(const Point& p) const = 0;
    virtual double radius_of(double value) const = 0;

protected:
    ~DartField() = default;
};

class RegionDarts {
public:
    // A dart kept by its cell's thinning and drawn in its free region.
    struct Dart {
        Point p;
        double t;            // time within the epoch, in [0, 1)
        VertexIndex source;  // the vertex whose cell it was drawn in
    };
    // A site's bound, measured while its darts were drawn.
    struct Bound {
        SiteIndex site;
        double weight;
    };
    // What one block of active sites drew; each on its own cache lines, as
    // the workers grow neighbouring blocks' lists at once.
    struct alignas(64) Block {
        std::vector<Dart> darts;
        std::vector<Bound> bounds;
    };

    // Mean darts per active cell in an epoch (at its bound), and the end: an
    // epoch that placed fewer points than kStopYield of its active cells.
    // Short epochs: their darts rarely meet, so few are drawn in vain
    // (docs/performance.md, 1.7.0).
    static constexpr double kDartsPerCell = 0.1;
    static constexpr double kStopYield = 1.0 / 128;
    static constexpr std::size_t kBlock = 4096;  // active sites per block

    // Starts the process, its streams keyed from epoch `epoch` on (the
    // opening's epochs come before), for points in `domain` at radius r;
    // on the torus (torus.on()) `domain` is ignored: the darts, drawn in
    // unclipped cells, are decided by their distances across the periods.
    // With a field (`varying`), r is its largest radius and each accepted
    // dart's own radius comes from the field that the decisions are given.
    void start(std::uint64_t salted_seed, std::size_t epoch, const Box& domain, double r,
               const Torus& torus = Torus{}, bool varying = false);
    void stop();
    bool on() const { return on_; }
    // Another mean for the tests: longer epochs, whose darts meet often.
    void set_darts_per_cell(double mean) { darts_per_cell_ = mean; }
    double darts_per_cell() const { return darts_per_cell_; }
    // The last epoch placed too few points: the process ends once they are out.
    bool ending() const { return ending_; }

    // The accepted darts, handed out in order of time.
    bool has_pending() const { return next_ < pending_.size(); }
    const Dart& pending() const { return pending_[next_]; }
    // With a field: the field's value at the next pending dart.
    bool has_values() const { return varying_; }
    double pending_value() const { return values_[next_]; }
    void pop() { ++next_; }
    // The pending darts, all of them (they do not change until the next epoch).
    const Dart* pending_darts() const { return pending_.data(); }
    std::size_t pending_count() const { return pending_.size(); }
    std::size_t next_index() const { return next_; }
    // The cells of the next n pending darts (fewer at the end).
    std::size_t sources_ahead(VertexIndex* out, std::size_t n) const {
        std::size_t m = 0;
        for (std::size_t i = next_; i < pending_.size() && m < n; ++i) out[m++] = pending_[i].source;
        return m;
    }

    // Epoch bookkeeping for the loop (jones_loop_regions.cpp runs it).
    std::uint64_t salted_seed() const { return salted_; }
    std::size_t epoch() const { return epoch_; }
    std::vector<SiteIndex>& active() { return active_; }
    const std::vector<SiteIndex>& active() const { return active_; }
    std::size_t listed() const { return listed_; }
    void set_listed(std::size_t sites) { listed_ = sites; }
    std::vector<Block>& blocks(std::size_t n);
    // Joins the blocks' darts in block order, decides them greedily by time
    // (by the radius given to start) and makes the accepted ones pending;
    // then commits the bounds through set(site, weight). Returns the number
    // accepted. With a field (required iff started varying): if it refuses
    // a dart, nothing is committed and the exception goes on.
    template <class SetBound>
    std::size_t decide_and_commit(std::size_t nblocks, const SetBound& set, const DartField* field = nullptr) {
        decide(nblocks, field);
        for (std::size_t b = 0; b < nblocks; ++b)
            for (const Bound& x : blocks_[b].bounds) set(x.site, x.weight);
        ++epoch_;
        ending_ = static_cast<double>(pending_.size()) < kStopYield * static_cast<double>(active_.size());
        return pending_.size();
    }

    // For tests and bench: epochs drawn, darts kept, points placed.
    struct Stats {
        std::size_t epochs = 0, darts = 0, points = 0;
    };
    const Stats& stats() const { return stats_; }

private:
    void decide(std::size_t nblocks, const DartField* field);
    // Dart i is free of the accepted darts in the grid (the plane's, and
    // the torus's, whose cells wrap around and divide the periods); with a
    // field (kVarying), of their own disks (reach_) within the largest
    // radius r_. Templates, so one radius pays no test per comparison.
    template <bool kVarying>
    bool free_in_plane(std::uint32_t i) const;
    template <bool kVarying>
    bool free_on_torus(std::uint32_t i) const;
    template <bool kVarying>
    bool free(std::uint32_t i) const {
        return torus_.on() ? free_on_torus<kVarying>(i) : free_in_plane<kVarying>(i);
    }
    // Takes back the accepted darts of an epoch left undecided.
    void undo_decision();
    std::size_t cell_of(const Point& q) const;  // the grid cell holding q (wrapped on the torus)
    std::size_t column_of(double x) const;
    std::size_t row_of(double y) const;

    bool on_ = false;
    bool ending_ = false;
    double darts_per_cell_ = kDartsPerCell;
    std::uint64_t salted_ = 0;
    std::size_t epoch_ = 0;
    double r_ = 0;                   // the decision's radius (a field's largest)
    std::size_t listed_ = 0;         // sites 0 .. listed_-1 were put on the active list
    std::vector<SiteIndex> active_;  // sites whose bound may be positive, in order
    std::vector<Block> blocks_;
    std::vector<Dart> darts_;             // the epoch's darts, in order of time
    std::vector<std::uint32_t> chain_;    // accepted darts of one grid cell
    std::vector<std::uint32_t> bucket_;   // the time sort's buckets
    std::vector<std::uint32_t> grid_;     // per cell of side 2R (at least): its last accepted dart
    double grid_x0_ = 0, grid_y0_ = 0;    // the grid's corner
    double side_x_ = 0, side_y_ = 0;      // its cells' sides
    std::size_t grid_columns_ = 0, grid_rows_ = 0;
    Torus torus_;                         // off in the plane
    bool varying_ = false;                // a field: each accepted dart has its own radius
    std::vector<double> reach_;           // with a field: an accepted dart's radius (by dart)
    std::vector<double> values_;          // with a field: the pending darts' values
    std::vector<Dart> pending_;           // accepted, in order of time
    std::size_t next_ = 0;
    Stats stats_;
};

}  // namespace pds

#endif
