// test_active_scan.cpp - the active list scanned in steps: whatever the
// number of steps before take(), the list kept and the sum of its bounds
// are those of one plain pass, bit for bit; a scan sealed midway leaves a
// list (kept sites, then the unread ones, in order) whose later scan gives
// that same list and sum; a scan dropped or sealed before any step leaves
// the list alone.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "jones/active_scan.hpp"
#include "jones/free_area_tree.hpp"
#include "suites.hpp"

namespace {

// 20,000 sites, about a third covered (bound 0), bounds over many scales
// (so the order of the sum shows in its last bits); the active list holds
// about 70% of them, ascending.
struct Sites {
    pds::FreeAreaTree tree;
    std::vector<pds::SiteIndex> active;
};

Sites make_sites(std::uint64_t seed) {
    constexpr std::size_t kSites = 20000;
    Sites s;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    s.tree.reserve(kSites);
    for (std::size_t i = 0; i < kSites; ++i) {
        s.tree.push_back(rng() % 3 == 0 ? 0.0 : u(rng) * std::ldexp(1.0, -static_cast<int>(rng() % 40)));
        if (rng() % 10 < 7) s.active.push_back(i);
    }
    return s;
}

// The plain pass: the sites of positive bound, in order, and their sum.
double plain_scan(const pds::FreeAreaTree& tree, std::vector<pds::SiteIndex>& active) {
    double total = 0.0;
    std::size_t kept = 0;
    for (const pds::SiteIndex site : active) {
        const double w = tree.weight(site);
        if (w > 0.0) {
            active[kept++] = site;
            total += w;
        }
    }
    active.resize(kept);
    return total;
}

}  // namespace

START_TEST(steps_then_take_give_one_pass) {
    Sites sites = make_sites(11);
    std::vector<pds::SiteIndex> expected = sites.active;
    const double expected_total = plain_scan(sites.tree, expected);
    ck_assert_uint_lt(expected.size(), sites.active.size());  // some were dropped
    for (const std::size_t steps : {0, 1, 3, 1000}) {
        std::vector<pds::SiteIndex> active = sites.active;
        pds::ActiveScan scan;
        scan.begin(active, sites.tree);
        ck_assert(scan.begun());
        for (std::size_t k = 0; k < steps && scan.step(); ++k) {
        }
        const double total = scan.take();
        ck_assert(!scan.begun());
        ck_assert(active == expected);
        ck_assert(total == expected_total);  // the same sum, bit for bit
    }
}
END_TEST

START_TEST(sealed_midway_scans_again_alike) {
    Sites sites = make_sites(12);
    std::vector<pds::SiteIndex> expected = sites.active;
    const double expected_total = plain_scan(sites.tree, expected);
    for (const std::size_t steps : {1, 2, 5}) {
        std::vector<pds::SiteIndex> active = sites.active;
        pds::ActiveScan scan;
        scan.begin(active, sites.tree);
        for (std::size_t k = 0; k < steps; ++k) ck_assert(scan.step());
        scan.seal();
        ck_assert(!scan.begun());
        // The read part is compacted, the unread part kept as it was.
        const std::size_t read = steps * pds::ActiveScan::kStep;
        std::vector<pds::SiteIndex> head(sites.active.begin(), sites.active.begin() + static_cast<long>(read));
        plain_scan(sites.tree, head);
        ck_assert_uint_eq(active.size(), head.size() + (sites.active.size() - read));
        for (std::size_t i = 0; i < active.size(); ++i)
            ck_assert_uint_eq(active[i], i < head.size() ? head[i] : sites.active[read + (i - head.size())]);
        // Scanned again, it ends as one pass over the whole list would.
        scan.begin(active, sites.tree);
        ck_assert(scan.take() == expected_total);
        ck_assert(active == expected);
    }
}
END_TEST

START_TEST(sealed_or_dropped_before_a_step_changes_nothing) {
    Sites sites = make_sites(13);
    std::vector<pds::SiteIndex> active = sites.active;
    pds::ActiveScan scan;
    scan.seal();  // none begun: nothing
    scan.begin(active, sites.tree);
    scan.seal();
    ck_assert(active == sites.active);
    scan.begin(active, sites.tree);
    scan.drop();
    ck_assert(!scan.begun());
    ck_assert(active == sites.active);
}
END_TEST

Suite* active_scan_suite() {
    Suite* s = suite_create("active_scan");
    TCase* t = tcase_create("scan");
    tcase_add_test(t, steps_then_take_give_one_pass);
    tcase_add_test(t, sealed_midway_scans_again_alike);
    tcase_add_test(t, sealed_or_dropped_before_a_step_changes_nothing);
    suite_add_tcase(s, t);
    return s;
}
