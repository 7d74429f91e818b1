/*
 * interpose.h - a counting, failing allocator for alloc_fail.c (interpose.c).
 *
 * interpose.c defines malloc, calloc, realloc, free, posix_memalign,
 * aligned_alloc and memalign, forwarding to glibc's __libc_* functions. The
 * program is linked with -rdynamic so that the library and libstdc++
 * (operator new calls malloc) bind to these definitions.
 *
 * Only allocations made while armed count: the test arms around each pds_*
 * call. The k-th armed allocation of a sequence can be made to fail, once
 * (NULL, or ENOMEM from posix_memalign). Blocks allocated while armed are tracked until
 * freed, so a leak shows up as a live block after pds_destroy.
 */
#ifndef PDS_TESTS_ALLOC_INTERPOSE_H
#define PDS_TESTS_ALLOC_INTERPOSE_H

/* Starts a sequence: counters and the live set cleared, no failure planned. */
void alloc_reset(void);
/* The k-th armed allocation of the sequence (counted from alloc_reset) fails. */
void alloc_fail_at(long k);
/* That k; 0 when none is planned. */
long alloc_fail_planned(void);
void alloc_arm(void);
void alloc_disarm(void);
/* Armed allocations attempted so far in this sequence. */
long alloc_armed_count(void);
/* Allocations failed on purpose so far (0 or 1). */
long alloc_failures(void);
/* Blocks allocated while armed and not freed yet; -1 if there were too many to track. */
long alloc_live(void);

#endif /* PDS_TESTS_ALLOC_INTERPOSE_H */
