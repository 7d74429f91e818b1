// test_law_torus.cpp - on the torus (Sampler::set_periodic) the sampler
// follows the random-sequential-adsorption law too: over many seeds, the
// distribution of the final count N and of the number of near-contact pairs
// (wrapped distance < 1.2 R) matches saturated dart throwing on the torus
// (dart_throwing.hpp with the Torus rule), independent of the library.
//
// The statistics and thresholds are law_compare.hpp's, as in the plane. A
// sampler that treats the seam as a wall packs extra points along it (about
// 0.23 per R of perimeter): N moves by many standard errors. The parallel
// process (set_threads) is held to the same law on 1, 2 and 3 threads.
#include <vector>

#include "dart_throwing.hpp"
#include "law_compare.hpp"
#include "suites.hpp"

namespace {

using law::Stages;

law::Config torus(const pds::Box& box, double r, int runs, Stages stages) {
    law::Config c;
    c.box = box;
    c.periodic = true;
    c.r = r;
    c.runs = runs;
    c.stages = stages;
    return c;
}

}  // namespace

START_TEST(torus_reference_is_maximal_and_spaced) {
    // The reference must saturate across the seam and keep wrapped spacing.
    const oracle::Torus unit{pds::Box{0, 0, 1, 1}};
    auto reference = oracle::dart_throwing(unit, oracle::ConstantRadius{0.1});
    for (int seed = 1; seed <= (test_light() ? 1 : 5); ++seed)
        law::assert_saturated(reference.run(static_cast<std::uint64_t>(seed)), unit, 200);
}
END_TEST

// Under Valgrind (PDS_TEST_LIGHT) a few dozen seeds: the thresholds stay
// valid, only the power drops, and the run stays short.
START_TEST(law_on_the_unit_torus) {
    law::compare(torus(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 60 : 3000, Stages::darts_then_jones));
}
END_TEST

START_TEST(law_on_a_rectangular_torus) {
    law::compare(torus(pds::Box{0, 0, 2, 0.5}, 0.12, test_light() ? 50 : 2000, Stages::darts_then_jones));
}
END_TEST

START_TEST(law_of_the_jones_loop_alone_on_the_torus) {
    law::compare(torus(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 50 : 2000, Stages::jones_only));
}
END_TEST

START_TEST(law_of_the_parallel_process_on_the_torus) {
    // The space-time dart process, its free regions' darts and the Jones
    // loop on 1, 2 and 3 threads (3 oversubscribes a 2-core machine). The
    // torus is long enough for four bands of rows: the first and the last
    // meet across the seam.
    law::Config c = torus(pds::Box{0, 0, 0.6, 2.4}, 0.1, test_light() ? 50 : 2000, Stages::darts_then_jones);
    c.threads = static_cast<unsigned>(_i);
    law::compare(c);
}
END_TEST

START_TEST(law_of_long_region_epochs_on_the_torus) {
    // Epochs 40 times as long as the default: darts of one epoch often fall
    // within R of one another, across the seams too.
    law::Config c = torus(pds::Box{0, 0, 0.6, 2.4}, 0.1, test_light() ? 50 : 2000, Stages::darts_then_jones);
    c.threads = static_cast<unsigned>(_i);
    c.region_darts_per_cell = 4.0;
    law::compare(c);
}
END_TEST

Suite* law_torus_suite() {
    Suite* s = suite_create("law_torus");
    TCase* t = tcase_create("random sequential adsorption on the torus");
    tcase_set_timeout(t, 900);
    tcase_add_test(t, torus_reference_is_maximal_and_spaced);
    tcase_add_test(t, law_on_the_unit_torus);
    tcase_add_test(t, law_on_a_rectangular_torus);
    tcase_add_test(t, law_of_the_jones_loop_alone_on_the_torus);
    tcase_add_loop_test(t, law_of_the_parallel_process_on_the_torus, 1, 4);
    tcase_add_loop_test(t, law_of_long_region_epochs_on_the_torus, 2, 4);
    suite_add_tcase(s, t);
    return s;
}
