// test_law.cpp - the sampler follows the random-sequential-adsorption law:
// over many seeds, the distribution of the final count N and of the number of
// near-contact pairs (distance < 1.2 R) matches saturated dart throwing
// (dart_throwing.hpp), an independent exact implementation of the same law.
//
// The comparison is law_compare.hpp's. A biased sampler fails it: picking cells uniformly instead of
// by area, or skipping the rejection step, shifts the mean N by many standard
// errors (see the closing note of the issue that introduced this test).
#include <algorithm>
#include <cmath>
#include <vector>

#include "dart_throwing.hpp"
#include "law_compare.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

using law::Stages;

void compare_laws(const pds::Box& box, double r, int runs, Stages stages) {
    law::Sample sampler, darts;
    SaturatedDartThrowing reference(box, r);
    const auto d2 = [](const pds::Point& a, const pds::Point& b) {
        return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
    };
    std::size_t from_darts = 0, total = 0;
    for (int seed = 1; seed <= runs; ++seed) {
        pds::Sampler s(r, static_cast<std::uint64_t>(seed));
        s.set_domain(box);
        if (stages == Stages::jones_only) s.skip_dart_stage();
        const std::vector<pds::Point> p = law::run_both_stages(s, &from_darts);
        total += p.size();
        law::add(sampler, p, r, d2);
        law::add(darts, reference.run(static_cast<std::uint64_t>(1000000 + seed)), r, d2);
    }
    if (stages == Stages::darts_then_jones) law::assert_both_stages(from_darts, total);
    law::assert_same_law(sampler, darts);
}

}  // namespace

START_TEST(reference_is_maximal) {
    // The reference itself must saturate: probe it densely.
    const pds::Box box{0, 0, 1, 1};
    const double r = 0.1;
    SaturatedDartThrowing reference(box, r);
    for (int seed = 1; seed <= 5; ++seed) {
        const std::vector<pds::Point> p = reference.run(static_cast<std::uint64_t>(seed));
        for (int i = 0; i <= 200; ++i)
            for (int j = 0; j <= 200; ++j) {
                const double x = i / 200.0, y = j / 200.0;
                bool near = false;
                for (const pds::Point& q : p)
                    if ((q.x - x) * (q.x - x) + (q.y - y) * (q.y - y) <= r * r) near = true;
                ck_assert(near);
            }
    }
}
END_TEST

START_TEST(law_in_the_unit_square) {
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 400 : 3000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_in_a_rectangle) {
    compare_laws(pds::Box{0, 0, 2, 0.5}, 0.12, test_light() ? 300 : 2000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_of_the_jones_loop_alone) {
    // The Jones loop from the first point (it alone serves refine()).
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 300 : 2000, Stages::jones_only);
}
END_TEST

Suite* law_suite() {
    Suite* s = suite_create("law");
    TCase* t = tcase_create("random sequential adsorption");
    tcase_set_timeout(t, 900);
    tcase_add_test(t, reference_is_maximal);
    tcase_add_test(t, law_in_the_unit_square);
    tcase_add_test(t, law_in_a_rectangle);
    tcase_add_test(t, law_of_the_jones_loop_alone);
    suite_add_tcase(s, t);
    return s;
}
