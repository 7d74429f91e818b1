// curve_order.cpp - BRIO rounds along a Hilbert curve (see curve_order.hpp).
#include "darts/curve_order.hpp"

#include <algorithm>

#include "core/worker_pool.hpp"
#include "darts/grid_arithmetic.hpp"

namespace pds {

CurveOrder::CurveOrder(const Box& box, double side_x, double side_y, std::size_t cols, std::size_t rows)
    : box_(box), inv_side_x_(1.0 / side_x), inv_side_y_(1.0 / side_y), cols_(cols), rows_(rows) {
    while ((std::size_t{1} << side_bits_) < std::max(cols_, rows_)) ++side_bits_;
}

void CurveOrder::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its vector as it was.
    order_.reserve(points);
    tmp_order_.reserve(points);
    key_.reserve(points);
    tmp_key_.reserve(points);
    counts_.reserve(kCounts);
}

namespace {

// The Hilbert curve as a state machine. Each level of the grid splits a cell
// into quadrants; the curve visits them in the order (0,0) (0,1) (1,1) (1,0)
// of the quadrant's (x, y) bits, after the level's transformation of the
// coordinates: a swap of x and y, a complement of both, both or neither (they
// commute, so four states: bit 0 swap, bit 1 complement). Entering quadrant
// (tx, 0) swaps, and (1, 0) also complements, for the levels below.
struct LevelStep {
    unsigned digit, state;
};
constexpr LevelStep level_step(unsigned state, unsigned bx, unsigned by) {
    unsigned tx = bx, ty = by;
    if (state & 2u) {
        tx ^= 1u;
        ty ^= 1u;
    }
    if (state & 1u) {
        const unsigned t = tx;
        tx = ty;
        ty = t;
    }
    unsigned next = state;
    if (ty == 0) next ^= tx != 0 ? 3u : 1u;
    return LevelStep{(3u * tx) ^ ty, next};
}

// Two levels at a time: entry [state][x1 y1 x0 y0] holds the two digits
// (4 bits) over the next state (2 bits). One level for an odd level count.
struct HilbertTables {
    std::uint8_t two[4][16] = {};
    std::uint8_t one[4][4] = {};
};
constexpr HilbertTables make_hilbert_tables() {
    HilbertTables t;
    for (unsigned state = 0; state < 4; ++state) {
        for (unsigned bits = 0; bits < 16; ++bits) {
            const LevelStep high = level_step(state, (bits >> 3) & 1u, (bits >> 2) & 1u);
            const LevelStep low = level_step(high.state, (bits >> 1) & 1u, bits & 1u);
            t.two[state][bits] = static_cast<std::uint8_t>((((high.digit << 2) | low.digit) << 2) | low.state);
        }
        for (unsigned bits = 0; bits < 4; ++bits) {
            const LevelStep step = level_step(state, bits >> 1, bits & 1u);
            t.one[state][bits] = static_cast<std::uint8_t>((step.digit << 2) | step.state);
        }
    }
    return t;
}
constexpr HilbertTables kHilbert = make_hilbert_tables();

}  // namespace

std::uint64_t CurveOrder::key(const Point& p) const {
    // Position along a Hilbert curve over the cells; nearby keys are nearby
    // cells. 64 bits: a side of up to 2^32 cells. By table, two levels a
    // step: the state is the only dependence between steps (branches on the
    // random quadrants, then masks, were most of the hand-over's sort).
    const std::uint64_t x = clamped_cell((p.x - box_.x0) * inv_side_x_, cols_);
    const std::uint64_t y = clamped_cell((p.y - box_.y0) * inv_side_y_, rows_);
    std::uint64_t key = 0;
    unsigned state = 0;
    int pairs = side_bits_ / 2;  // levels below the top one of an odd count
    if (side_bits_ & 1) {
        const int level = side_bits_ - 1;
        const unsigned e = kHilbert.one[state][(((x >> level) & 1u) << 1) | ((y >> level) & 1u)];
        key = e >> 2;
        state = e & 3u;
    }
    while (pairs-- > 0) {
        const int level = 2 * pairs;
        const unsigned bx = static_cast<unsigned>((x >> level) & 3u), by = static_cast<unsigned>((y >> level) & 3u);
        const unsigned e = kHilbert.two[state][((bx & 2u) << 2) | ((by & 2u) << 1) | ((bx & 1u) << 1) | (by & 1u)];
        key = (key << 4) | (e >> 2);
        state = e & 3u;
    }
    return key;
}

const std::uint32_t* CurveOrder::order(const std::vector<Point>& points, unsigned threads, std::size_t first) {
    // Sizes within the reserved capacity: no allocation.
    const std::size_t n = points.size();
    order_.resize(n);
    tmp_order_.resize(n);
    key_.resize(n);
    tmp_key_.resize(n);
    counts_.resize(kCounts);
    // The fixed points among themselves, then the others.
    sort(points, 0, first, order_.data(), key_.data(), tmp_order_.data(), tmp_key_.data(), counts_.data(), threads);
    sort(points, first, n, order_.data() + first, key_.data(), tmp_order_.data(), tmp_key_.data(), counts_.data(),
         threads);
    return order_.data();
}

std::vector<std::uint32_t> CurveOrder::fresh_order(const std::vector<Point>& points) const {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> order(n), tmp_order(n);
    std::vector<std::uint64_t> key(n), tmp_key(n);
    std::vector<std::uint32_t> counts(kCounts);
    sort(points, 0, n, order.data(), key.data(), tmp_order.data(), tmp_key.data(), counts.data(), 1);
    return order;
}

void CurveOrder::sort(const std::vector<Point>& points, std::size_t first, std::size_t last, std::uint32_t* order,
                      std::uint64_t* key, std::uint32_t* tmp_order, std::uint64_t* tmp_key, std::uint32_t* counts,
                      unsigned threads) const {
    const std::size_t n = last - first;
    std::size_t ends[64];
    std::size_t rounds = 0;
    for (std::size_t end = n; end > 0; end = end > 256 ? end / 4 : 0) ends[rounds++] = end;
    // Keys have 2 log2(side) bits: enough 11-bit radix passes to cover them.
    // The side stays below 2^30 cells: a dart stage runs only when Oler's
    // bound fits the index type (sampler.cpp), and a grid k cells long has
    // a bound of at least k/1.43 points; so keys fit 64 bits.
    const int key_bits = 2 * side_bits_;
    constexpr std::uint32_t kMask = (std::uint32_t{1} << kDigit) - 1;
    // Side by side only where it pays; worker w's counts at counts[w << kDigit].
    WorkerPool pool(n >= kSideBySideFrom ? std::min(threads, kMaxWorkers) : 1);
    const unsigned workers = pool.size();
    pool.run([&](unsigned w) {
        for (std::size_t i = n * w / workers, end = n * (w + 1) / workers; i < end; ++i) {
            key[i] = this->key(points[first + i]);
            order[i] = static_cast<std::uint32_t>(first + i);
        }
    });
    const auto count = [counts](unsigned w) { return counts + (std::size_t{w} << kDigit); };
    std::size_t begin = 0;
    for (std::size_t r = rounds; r-- > 0;) {
        const std::size_t end = ends[r], size = end - begin;
        // Stable LSD radix sort of [begin, end) by key, passes alternating
        // between the arrays and the scratch. Worker w counts and then
        // scatters its own slice; the slices' places follow from all the
        // counts in slice order, so the result is the one-worker sort.
        const unsigned parts = size >= kSideBySideFrom ? workers : 1;
        const auto slice = [&](unsigned w) { return begin + size * w / parts; };
        const auto in_parts = [&](const auto& task) {
            if (parts > 1)
                pool.run(task);  // parts is then the pool's size
            else
                task(0u);
        };
        std::uint64_t *from_key = key, *to_key = tmp_key;
        std::uint32_t *from_order = order, *to_order = tmp_order;
        for (int shift = 0; shift < key_bits; shift += kDigit) {
            const auto digit = [&](std::size_t i) { return static_cast<std::uint32_t>(from_key[i] >> shift) & kMask; };
            const auto tally = [&](unsigned w) {
                std::fill(count(w), count(w) + kMask + 1, 0u);
                for (std::size_t i = slice(w), e = slice(w + 1); i < e; ++i) ++count(w)[digit(i)];
            };
            const auto scatter = [&](unsigned w) {
                for (std::size_t i = slice(w), e = slice(w + 1); i < e; ++i) {
                    const std::size_t at = begin + count(w)[digit(i)]++;
                    to_key[at] = from_key[i];
                    to_order[at] = from_order[i];
                }
            };
            in_parts(tally);
            // Each slice's first place for each digit.
            std::uint32_t at = 0;
            for (std::uint32_t d = 0; d <= kMask; ++d)
                for (unsigned w = 0; w < parts; ++w) {
                    const std::uint32_t c = count(w)[d];
                    count(w)[d] = at;
                    at += c;
                }
            in_parts(scatter);
            std::swap(from_key, to_key);
            std::swap(from_order, to_order);
        }
        if (from_key != key) {
            std::copy(from_key + begin, from_key + end, key + begin);
            std::copy(from_order + begin, from_order + end, order + begin);
        }
        begin = end;
    }
}

}  // namespace pds
