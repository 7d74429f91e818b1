// test_worker_pool.cpp - the worker pool: every task index runs once a run,
// and run() returns only after all of them, whether the helpers waited for
// it awake or asleep, and whether the caller waits for them awake or asleep;
// tasks run at the same time (they may wait for one another); a helper's
// exception reaches the caller and the pool goes on.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "alloc_hook.hpp"
#include "core/worker_pool.hpp"
#include "suites.hpp"

namespace {

// Long enough that a waiting thread has gone to sleep (it waits awake for
// about 50 microseconds).
void pause_long() { std::this_thread::sleep_for(std::chrono::microseconds(300)); }

// Under Valgrind the threads take turns: fewer runs.
unsigned runs(unsigned natively) { return alloc_hook::in_effect() ? natively : natively / 20; }

}  // namespace

START_TEST(every_task_runs_once_a_run_and_is_done_when_run_returns) {
    // As many workers as this machine's two cores, then more (they take turns).
    for (const unsigned wanted : {2u, 4u}) {
        pds::WorkerPool pool(wanted);
        const unsigned workers = pool.size();
        ck_assert_uint_ge(workers, 1);
        // Plain slots: the caller reads them after run() without a lock, so
        // they must be written before the helpers report their end.
        std::vector<unsigned> last(workers, 0), count(workers, 0);
        const unsigned n = runs(wanted == 2 ? 10000 : 1000);
        for (unsigned r = 1; r <= n; ++r) {
            // Most runs follow one another at once (helpers still awake);
            // every 64th comes after a pause (helpers asleep, woken by it).
            if (r % 64 == 0) pause_long();
            pool.run([&](unsigned w) {
                // Every 97th run a helper is slow, so the caller sleeps too.
                if (r % 97 == 0 && w == workers - 1) pause_long();
                last[w] = r;
                ++count[w];
            });
            for (unsigned w = 0; w < workers; ++w)
                ck_assert_msg(last[w] == r, "%u workers, run %u: worker %u last ran in run %u", workers, r, w,
                              last[w]);
        }
        for (unsigned w = 0; w < workers; ++w) ck_assert_uint_eq(count[w], n);
    }
}
END_TEST

START_TEST(tasks_run_at_the_same_time) {
    // Each task waits until every task of its run has started: this ends
    // only if each runs on its own thread.
    pds::WorkerPool pool(3);
    const unsigned workers = pool.size();
    std::atomic<unsigned> arrived{0};
    const unsigned n = runs(1000);
    for (unsigned r = 1; r <= n; ++r) {
        if (r % 50 == 0) pause_long();
        pool.run([&](unsigned) {
            arrived.fetch_add(1, std::memory_order_acq_rel);
            while (arrived.load(std::memory_order_acquire) < r * workers) std::this_thread::yield();
        });
        ck_assert_uint_eq(arrived.load(), r * workers);
    }
}
END_TEST

START_TEST(a_helpers_exception_reaches_the_caller_and_the_pool_goes_on) {
    pds::WorkerPool pool(3);
    const unsigned workers = pool.size();
    if (workers < 2) return;  // no thread could start here: nothing to test
    for (int round = 0; round < 3; ++round) {
        bool thrown = false;
        try {
            pool.run([&](unsigned w) {
                if (w == workers - 1) throw std::runtime_error("helper");
            });
        } catch (const std::runtime_error&) {
            thrown = true;
        }
        ck_assert_msg(thrown, "round %d: the helper's exception did not reach the caller", round);
        std::vector<unsigned> ran(workers, 0);
        pool.run([&](unsigned w) { ran[w] = 1; });
        for (unsigned w = 0; w < workers; ++w) ck_assert_uint_eq(ran[w], 1);
        pause_long();  // the next round finds the helpers asleep
    }
}
END_TEST

START_TEST(a_pool_ends_whether_its_helpers_wait_awake_or_asleep) {
    // Destroyed right after a run (helpers awake) and after a pause (asleep):
    // both must join, or the test times out.
    for (int i = 0; i < 50; ++i) {
        pds::WorkerPool pool(3);
        std::atomic<unsigned> ran{0};
        pool.run([&](unsigned) { ran.fetch_add(1); });
        ck_assert_uint_eq(ran.load(), pool.size());
        if (i % 2) pause_long();
    }
}
END_TEST

Suite* worker_pool_suite() {
    Suite* s = suite_create("worker_pool");
    TCase* t = tcase_create("runs");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, every_task_runs_once_a_run_and_is_done_when_run_returns);
    tcase_add_test(t, tasks_run_at_the_same_time);
    tcase_add_test(t, a_helpers_exception_reaches_the_caller_and_the_pool_goes_on);
    tcase_add_test(t, a_pool_ends_whether_its_helpers_wait_awake_or_asleep);
    suite_add_tcase(s, t);
    return s;
}
