/*
 * perf_counter.h - count the user-space instructions of a region of this
 * process with Linux perf_event_open (PERF_COUNT_HW_INSTRUCTIONS). Many
 * virtual machines expose no hardware counters; then opening fails and the
 * benchmark prints "-" instead of a figure.
 */
#ifndef BENCH_PERF_COUNTER_H
#define BENCH_PERF_COUNTER_H

struct perf_counter {
    int fd; /* -1 when the kernel refused the counter */
};

/* Returns 0, or -1 if the counter is unavailable (c->fd is then -1). */
int perf_counter_open(struct perf_counter *c);
/* Zero and start the counter; no-op when unavailable. */
void perf_counter_start(struct perf_counter *c);
/* Stop it; returns the count since start, or -1 when it is unavailable. */
double perf_counter_stop(struct perf_counter *c);
void perf_counter_close(struct perf_counter *c);

#endif /* BENCH_PERF_COUNTER_H */
