/* pattern_check_test.h - bench --self-test: the pattern checks on known patterns. */
#ifndef BENCH_PATTERN_CHECK_TEST_H
#define BENCH_PATTERN_CHECK_TEST_H

#include <stdio.h>

/* Returns 0 when every case passes; reports failures on log. */
int pattern_check_self_test(FILE *log);

#endif /* BENCH_PATTERN_CHECK_TEST_H */
