/*
 * interpose.c - the counting, failing allocator of alloc_fail.c; see interpose.h.
 *
 * No function here may allocate through malloc itself: the live set is a
 * fixed table, and everything forwards to glibc's __libc_* entry points.
 * The library's worker threads (pds_set_threads) allocate too: every entry
 * point holds one spin lock while it counts, fails or tracks a block.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "interpose.h"

extern void *__libc_malloc(size_t size);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t size);
extern void __libc_free(void *p);
extern void *__libc_memalign(size_t alignment, size_t size);

void *aligned_alloc(size_t alignment, size_t size);
void *memalign(size_t alignment, size_t size);

static int armed;         /* inside a pds_* call */
static long armed_count;  /* armed allocations so far in this sequence */
static long fail_at;      /* the armed allocation to fail; 0: none */
static long failures;     /* how many were failed (at most 1) */

/* Live blocks allocated while armed: open addressing, linear probing. */
#define LIVE_SLOTS (1u << 16)
static void *live[LIVE_SLOTS];
static long live_count;
static int live_overflow;

static size_t slot_of(const void *p)
{
    uintptr_t h = (uintptr_t)p >> 4;
    return (size_t)((h * 0x9E3779B97F4A7C15ull) >> 48) & (LIVE_SLOTS - 1);
}

static void live_add(void *p)
{
    size_t i = slot_of(p), n;
    for (n = 0; n < LIVE_SLOTS; n++, i = (i + 1) & (LIVE_SLOTS - 1)) {
        if (live[i] == NULL) {
            live[i] = p;
            live_count++;
            return;
        }
    }
    live_overflow = 1;
}

/* Removes p if tracked (backward-shift deletion keeps probe chains intact). */
static int live_remove(void *p)
{
    size_t i = slot_of(p), n, j;
    for (n = 0; n < LIVE_SLOTS && live[i] != p; n++, i = (i + 1) & (LIVE_SLOTS - 1))
        if (live[i] == NULL)
            return 0;
    if (n == LIVE_SLOTS)
        return 0;
    live[i] = NULL;
    live_count--;
    for (j = (i + 1) & (LIVE_SLOTS - 1); live[j] != NULL; j = (j + 1) & (LIVE_SLOTS - 1)) {
        size_t home = slot_of(live[j]);
        /* Move live[j] into the hole at i unless its home lies in (i, j]. */
        if ((j > i && (home <= i || home > j)) || (j < i && home <= i && home > j)) {
            live[i] = live[j];
            live[j] = NULL;
            i = j;
        }
    }
    return 1;
}

static char lock_word;

static void lock(void)
{
    while (__atomic_test_and_set(&lock_word, __ATOMIC_ACQUIRE)) {
    }
}

static void unlock(void) { __atomic_clear(&lock_word, __ATOMIC_RELEASE); }

/* Called before every allocation: 1 means "fail this one". */
static int must_fail(void)
{
    if (!armed)
        return 0;
    armed_count++;
    if (armed_count != fail_at)
        return 0;
    failures++;
    return 1;
}

static void *tracked(void *p)
{
    if (p != NULL && armed)
        live_add(p);
    return p;
}

void *malloc(size_t size)
{
    void *p;
    lock();
    p = must_fail() ? NULL : tracked(__libc_malloc(size));
    unlock();
    return p;
}

void *calloc(size_t n, size_t size)
{
    void *p;
    lock();
    p = must_fail() ? NULL : tracked(__libc_calloc(n, size));
    unlock();
    return p;
}

void *realloc(void *p, size_t size)
{
    void *q;
    int was_tracked;
    lock();
    if (must_fail()) {
        unlock();
        return NULL; /* the old block stays valid, as with a real failure */
    }
    q = __libc_realloc(p, size);
    if (q == NULL && size != 0) {
        unlock();
        return NULL;
    }
    was_tracked = p != NULL && live_remove(p);
    if (q != NULL && (was_tracked || armed))
        live_add(q);
    unlock();
    return q;
}

void free(void *p)
{
    lock();
    if (p != NULL)
        live_remove(p);
    __libc_free(p);
    unlock();
}

int posix_memalign(void **out, size_t alignment, size_t size)
{
    void *p;
    if (alignment % sizeof(void *) != 0 || (alignment & (alignment - 1)) != 0)
        return EINVAL;
    lock();
    p = must_fail() ? NULL : tracked(__libc_memalign(alignment, size));
    unlock();
    if (p == NULL)
        return ENOMEM;
    *out = p;
    return 0;
}

void *aligned_alloc(size_t alignment, size_t size)
{
    void *p;
    lock();
    p = must_fail() ? NULL : tracked(__libc_memalign(alignment, size));
    unlock();
    return p;
}

void *memalign(size_t alignment, size_t size)
{
    void *p;
    lock();
    p = must_fail() ? NULL : tracked(__libc_memalign(alignment, size));
    unlock();
    return p;
}

void alloc_reset(void)
{
    memset(live, 0, sizeof live);
    live_count = 0;
    live_overflow = 0;
    armed = 0;
    armed_count = 0;
    fail_at = 0;
    failures = 0;
}

void alloc_fail_at(long k) { fail_at = k; }
long alloc_fail_planned(void) { return fail_at; }

void alloc_arm(void) { armed = 1; }
void alloc_disarm(void) { armed = 0; }
long alloc_armed_count(void) { return armed_count; }
long alloc_failures(void) { return failures; }
long alloc_live(void) { return live_overflow ? -1 : live_count; }
