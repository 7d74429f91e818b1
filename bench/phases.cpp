// phases.cpp - where the time of one run goes (make bench-phases).
//
//   build/bench-phases [--check] [--threads N [--sides]] [N [SEED]]
//
// Samples the unit square at R = sqrt(0.6966/N) (the bench's radius) with the
// library's own stages, called one by one in the order pds_run calls them.
//
// The default process (no --threads): the dart stage, the hand-over's
// insertion order, the hand-over itself (triangulating the dart points,
// measuring every cell, building the tree) and the Jones loop. It prints each
// phase's time with what it counted: darts thrown, and the loop's cell
// selections with those a stale bound rejected (the lazy areas of
// jones_loop.hpp). The measuring part of the hand-over is timed by measuring
// every cell once more afterwards, the insertion is the rest.
//
// The parallel process (--threads N, as pds_set_threads(s, N)): the opening's
// epochs, the hand-over (order, mesh built whole, every cell measured), the
// free regions' epochs (draws side by side, decisions on the caller's
// thread), their points' insertions (on the caller's thread alone) and the
// Jones loop's last points. Run with N = 1 and 2 and compare the rows: the
// insertions are the part that does not shrink with more threads. The
// clock is read at each epoch's draw, not at each point, so the rows carry
// no clock reads a point.
//
// Wall-clock times of one run: compare phases within a run, and runs on one
// machine.
//
// --sides (with --threads) inserts each free regions' epoch on two sides at
// once (JonesStage::set_side_insertions, off in the library for now): the
// insertions are then timed in the epochs' row, and --check is refused.
//
// --check also runs pds_run with the same radius, seed and threads, and fails
// unless both give the same points, coordinate for coordinate: what is timed
// here is the library's path, not an imitation of it (make check-bench runs
// it).
//
// A developer's tool: it includes the library's internal headers (src/) and
// links its static archive.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "darts/dart_stage.hpp"
#include "darts/space_time_stage.hpp"
#include "jones/jones_stage.hpp"
#include "jones/mesh_cells.hpp"
#include "poissondisk.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int usage() {
    std::fprintf(stderr,
                 "usage: bench-phases [--check] [--threads N [--sides]] [N [SEED]]"
                 "   (N >= 100, default 1000000; SEED default 1;"
                 " threads 1 to 64)\n");
    return 2;
}

// The points of a pds_run with the same radius and seed (and threads, if
// not 0: the parallel process); false on an error.
bool library_points(double radius, std::uint64_t seed, unsigned threads, std::vector<double>* xy) {
    pds_sampler* s = nullptr;
    if (pds_create(&s, radius, seed) != 0) return false;
    bool ok = threads == 0 || pds_set_threads(s, threads) == 0;
    ok = ok && pds_run(s, 0, nullptr) == PDS_DONE;
    if (ok) {
        xy->resize(2 * pds_count(s));
        ok = pds_points(s, 0, pds_count(s), xy->data()) == pds_count(s);
    }
    pds_destroy(s);
    return ok;
}

// --check: whether pds_run gives the points the stages gave; prints the verdict.
template <class PointAt>
int check_against_library(double radius, std::uint64_t seed, unsigned threads, std::size_t total,
                          const PointAt& point_at) {
    std::vector<double> xy;
    if (!library_points(radius, seed, threads, &xy)) {
        std::fprintf(stderr, "bench-phases: pds_run failed\n");
        return 1;
    }
    bool same = xy.size() == 2 * total;
    for (std::size_t k = 0; same && k < total; ++k) {
        const pds::Point p = point_at(k);
        same = xy[2 * k] == p.x && xy[2 * k + 1] == p.y;
    }
    std::printf("check: pds_run gives %zu points, %s\n", xy.size() / 2, same ? "the same" : "NOT the same");
    return same ? 0 : 1;
}

double per(double a, std::size_t b) { return b == 0 ? 0.0 : a / static_cast<double>(b); }

// What both processes are timed on: the unit square at R = sqrt(0.6966/N),
// with room for 1.2 N + 1000 points (a maximal pattern holds about 1.0 N).
struct Setup {
    explicit Setup(double n_target)
        : radius(std::sqrt(0.6966 / n_target)), room(static_cast<std::size_t>(1.2 * n_target) + 1000) {}
    double radius;
    pds::Box square{0.0, 0.0, 1.0, 1.0};
    std::size_t room;
};

// The parallel process on `threads` threads, as Sampler::prepare sets it up:
// the space-time opening, then the Jones stage, which carries the darts on
// in the free regions from the hand-over.
int parallel_phases(double n_target, std::uint64_t seed, unsigned threads, bool sides, bool check) {
    using Clock = std::chrono::steady_clock;
    const Setup setup(n_target);
    const double radius = setup.radius;
    const pds::Box& square = setup.square;
    const std::size_t room = setup.room;
    pds::Rng rng(seed);
    pds::SpaceTimeDartStage opening(square, nullptr, radius, seed);
    const auto jones_stage = pds::make_jones_stage(square, radius);
    pds::JonesStage& jones = *jones_stage;
    jones.set_threads(threads);
    jones.allow_helper(true);  // as pds_run does
    jones.set_side_insertions(sides);
    opening.set_threads(threads);
    opening.reserve(room);
    jones.reserve(room);

    auto t = Clock::now();
    while (opening.next(rng)) opening.add_next();
    const double t_opening = seconds_since(t);
    const std::size_t opened = opening.count(), epochs = opening.epochs();

    t = Clock::now();
    opening.hand_over_to(jones);
    const double t_handover = seconds_since(t);

    // A point is the free regions' while the process has made more points
    // than it has handed out. Once it has handed out all it made, the next
    // call draws an epoch (made grows), or the process has ended and the
    // call is the loop's. The clock is read there only, not at each point:
    // an epoch's insertions run from the end of its draw to the next draw,
    // and the loop's points from the process's end to the run's.
    double t_epochs = 0.0, t_insert = 0.0, t_loop = 0.0;
    std::size_t region_points = 0, loop_points = 0;
    bool in_region = true;
    auto mark = Clock::now();  // the start of the span under way
    for (;;) {
        const pds::Point* p;
        if (in_region && region_points == jones.region_stats().points) {
            const auto t0 = Clock::now();
            t_insert += std::chrono::duration<double>(t0 - mark).count();
            p = jones.next(rng);
            mark = Clock::now();
            in_region = region_points < jones.region_stats().points;
            (in_region ? t_epochs : t_loop) += std::chrono::duration<double>(mark - t0).count();
        } else {
            p = jones.next(rng);
        }
        if (p == nullptr) break;
        jones.add_next();
        ++(in_region ? region_points : loop_points);
    }
    if (!in_region) t_loop += seconds_since(mark);
    const pds::RegionDarts::Stats& rs = jones.region_stats();
    const std::size_t total = jones.count();
    const double t_all = t_opening + t_handover + t_epochs + t_insert + t_loop;
    const auto share = [&](double x) { return 100.0 * x / t_all; };

    std::printf("poissondisk %s phases, parallel process on %u thread%s%s: unit square, N=%.0f, R=%.6g, seed %llu: "
                "%zu points\n",
                pds_version_string(), threads, threads == 1 ? "" : "s", sides ? ", epochs by sides" : "", n_target,
                radius, static_cast<unsigned long long>(seed), total);
    std::printf("phase                 seconds  share     points  per point  counted\n");
    std::printf("opening epochs       %8.4f  %4.1f%%  %9zu  %6.0f ns  %zu epochs\n", t_opening, share(t_opening),
                opened, 1e9 * per(t_opening, opened), epochs);
    std::printf("hand-over            %8.4f  %4.1f%%  %9zu  %6.0f ns  (order, mesh built whole, every cell measured)\n",
                t_handover, share(t_handover), opened, 1e9 * per(t_handover, opened));
    std::printf("region epochs        %8.4f  %4.1f%%  %9zu  %6.0f ns  %zu epochs, %zu darts kept, %zu points placed "
                "(drawn side by side, decided on the caller's thread)\n",
                t_epochs, share(t_epochs), region_points, 1e9 * per(t_epochs, region_points), rs.epochs, rs.darts,
                rs.points);
    std::printf("region insertions    %8.4f  %4.1f%%  %9zu  %6.0f ns  (on the caller's thread alone)\n", t_insert,
                share(t_insert), region_points, 1e9 * per(t_insert, region_points));
    std::printf("Jones loop           %8.4f  %4.1f%%  %9zu  %6.0f ns\n", t_loop, share(t_loop), loop_points,
                1e9 * per(t_loop, loop_points));
    std::printf("total                %8.4f  100%%   %9zu  %6.0f ns\n", t_all, total, 1e9 * per(t_all, total));
    if (!check) return 0;
    return check_against_library(radius, seed, threads, total, [&](std::size_t k) { return jones.point(k); });
}

}  // namespace

int main(int argc, char** argv) {
    bool check = false;
    int arg = 1;
    if (arg < argc && std::strcmp(argv[arg], "--check") == 0) {
        check = true;
        ++arg;
    }
    unsigned threads = 0;  // 0: the default process
    char* end = nullptr;
    if (arg < argc && std::strcmp(argv[arg], "--threads") == 0) {
        if (++arg == argc) return usage();
        const unsigned long n = std::strtoul(argv[arg++], &end, 10);
        if (*end != '\0' || n < 1 || n > 64) return usage();
        threads = static_cast<unsigned>(n);
    }
    bool sides = false;
    if (arg < argc && std::strcmp(argv[arg], "--sides") == 0) {
        if (threads == 0 || check) return usage();
        sides = true;
        ++arg;
    }
    double n_target = 1e6;
    std::uint64_t seed = 1;
    if (arg < argc) {
        n_target = std::strtod(argv[arg++], &end);
        if (*end != '\0' || !(n_target >= 100.0 && n_target <= 1e9)) return usage();
    }
    if (arg < argc) {
        seed = std::strtoull(argv[arg++], &end, 10);
        if (*end != '\0') return usage();
    }
    if (arg != argc) return usage();
    if (threads != 0) return parallel_phases(n_target, seed, threads, sides, check);

    const Setup setup(n_target);
    const double radius = setup.radius;
    const pds::Box& square = setup.square;
    const std::size_t room = setup.room;
    pds::Rng rng(seed);
    pds::DartStage darts(square, nullptr, radius);
    const auto jones_stage = pds::make_jones_stage(square, radius);
    pds::JonesStage& jones = *jones_stage;
    darts.reserve(room);
    jones.reserve(room);

    auto t = std::chrono::steady_clock::now();
    while (darts.next(rng)) darts.add_next();
    const double t_darts = seconds_since(t);
    const std::size_t dart_points = darts.count(), thrown = darts.darts_thrown();

    t = std::chrono::steady_clock::now();
    const std::uint32_t* order = darts.handover_order();
    const double t_order = seconds_since(t);

    t = std::chrono::steady_clock::now();
    jones.adopt(darts.points(), order);
    const double t_adopt = seconds_since(t);

    // The measuring part of the hand-over, timed once more on its own.
    t = std::chrono::steady_clock::now();
    const double free_area = jones.cells().total_free_area();
    const double t_measure = seconds_since(t);

    t = std::chrono::steady_clock::now();
    while (jones.next(rng)) jones.add_next();
    const double t_loop = seconds_since(t);

    // The measuring timed alone can exceed its share of the hand-over on a
    // loaded machine (small runs); the insertion's time is then taken as 0.
    const double t_insert = std::max(0.0, t_adopt - t_measure);
    const std::size_t total = jones.count(), loop_points = total - dart_points;
    const pds::JonesStats& st = jones.stats();
    const double t_all = t_darts + t_order + t_adopt + t_loop;
    const auto share = [&](double x) { return 100.0 * x / t_all; };

    std::printf("poissondisk %s phases: unit square, N=%.0f, R=%.6g, seed %llu: %zu points\n",
                pds_version_string(), n_target, radius, static_cast<unsigned long long>(seed), total);
    std::printf("phase                 seconds  share     points  per point  counted\n");
    std::printf("darts                %8.4f  %4.1f%%  %9zu  %6.0f ns  %zu darts thrown (%.2f per point, %.1f ns each)\n",
                t_darts, share(t_darts), dart_points, 1e9 * per(t_darts, dart_points), thrown,
                per(static_cast<double>(thrown), dart_points), 1e9 * per(t_darts, thrown));
    std::printf("hand-over order      %8.4f  %4.1f%%  %9zu  %6.0f ns\n", t_order, share(t_order), dart_points,
                1e9 * per(t_order, dart_points));
    std::printf("hand-over insert     %8.4f  %4.1f%%  %9zu  %6.0f ns  (the hand-over less the measuring)\n",
                t_insert, share(t_insert), dart_points, 1e9 * per(t_insert, dart_points));
    std::printf("hand-over measure    %8.4f  %4.1f%%  %9zu  %6.0f ns  free area %.4g of the square at the switch\n",
                t_measure, share(t_measure), dart_points, 1e9 * per(t_measure, dart_points), free_area);
    std::printf("Jones loop           %8.4f  %4.1f%%  %9zu  %6.0f ns  %zu selections (%.2f per point), %zu stale, "
                "%zu of them at zero area\n",
                t_loop, share(t_loop), loop_points, 1e9 * per(t_loop, loop_points), st.selections,
                per(static_cast<double>(st.selections), loop_points), st.stale_selections, st.stale_at_zero);
    std::printf("total                %8.4f  100%%   %9zu  %6.0f ns\n", t_all, total, 1e9 * per(t_all, total));

    if (!check) return 0;
    return check_against_library(radius, seed, 0, total, [&](std::size_t k) { return jones.point(k); });
}
